#include "commands.h"

namespace woven {

void addCommands(CLI::App& app) {
    addPatternCommand(app);
    addFabricsCommand(app);
    addBsdfCommands(app);
    addPreviewCommand(app);
    addRenderCommand(app);
    addConvergeCommand(app);
    addMergeCommand(app);
    addSubmitCommand(app);
    addExportCommands(app);
    addFitCommand(app);
    app.require_subcommand(1);
}

}  // namespace woven
