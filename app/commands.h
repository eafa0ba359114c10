#pragma once
// Each subcommand of `woven` registers its options and its action on the CLI11 app.
#include <CLI/CLI.hpp>

namespace woven {

void addPatternCommand(CLI::App& app);
void addFabricsCommand(CLI::App& app);  // docs/FABRICS.md
void addBsdfCommands(CLI::App& app);  // bsdf-eval, bsdf-plot
void addPreviewCommand(CLI::App& app);
void addRenderCommand(CLI::App& app);
void addConvergeCommand(CLI::App& app);
void addMergeCommand(CLI::App& app);
void addSubmitCommand(CLI::App& app);  // docs/CLUSTER.md
void addExportCommands(CLI::App& app);  // export, bake, share (docs/EXPORT.md)
void addFitCommand(CLI::App& app);  // docs/FIT.md

// Every command above, in the order `woven --help` lists them, one of them required (main(),
// fuzz/fuzz_options); no option of any takes an empty value.
void addCommands(CLI::App& app);

}  // namespace woven
