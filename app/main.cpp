// `woven`: the command-line entry point; one subcommand per job.
#include <exception>
#include <iostream>

#include "commands.h"
#include "file_reading.h"
#include "parse_errors.h"
#include "version.h"

int main(int argc, char** argv) {
    CLI::App app{"woven: a renderer for woven fabric"};
    app.set_version_flag("--version", std::string("woven ") + woven::wovenVersion() + " (commit " + woven::wovenCommit() + ")",
                         "print the version and the git commit woven was built from, and exit");
    woven::addCommands(app);
    // Every file the command reads is an input none of its outputs may replace (output_path.h).
    woven::rememberInputs(true);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return woven::reportParseError(app, e, argc, argv);
    } catch (const std::exception& e) {
        std::cerr << "woven: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
