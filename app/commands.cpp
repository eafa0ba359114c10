#include "commands.h"

namespace woven {

namespace {

// An empty value ('') names nothing. Options whose empty string stands for "not given" ignored
// it: `render -o ''` wrote the default name, `--environment ''` and `--camera ''` kept the scene's.
void refuseEmptyValues(CLI::App& app) {
    const CLI::Validator notEmpty(
        [](std::string& text) {
            return text.empty() ? std::string("'' names nothing: give a value, or leave the option out") : std::string();
        },
        "");
    for (CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; })) {
        for (CLI::Option* option : command->get_options())
            if (option->get_type_size_max() > 0) option->check(notEmpty);
        refuseEmptyValues(*command);
    }
}

}  // namespace

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
    refuseEmptyValues(app);
}

}  // namespace woven
