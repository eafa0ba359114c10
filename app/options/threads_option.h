#pragma once
// --threads, as render, converge and fit take it: a whole number, 0 for all the cores this
// process may use. More than that is valid (a job script written for a larger machine) and is
// capped by the renderer; the option says so, once, on stderr.
#include <CLI/CLI.hpp>

#include <string>

namespace woven {

CLI::Option* addThreadsOption(CLI::App& command, int& threads, const std::string& help);

}  // namespace woven
