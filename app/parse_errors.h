#pragma once
// woven's words for the command line's parse errors. CLI11 says "A subcommand is required" for a
// mistyped command and "The following arguments were not expected" for a mistyped option; a user
// needs the name they meant. Help requests are printed as CLI11 prints them.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace woven {

// The candidate closest to `word` by edit distance, if it is close enough to be a typo of it
// (at most a third of its letters, rounded up, changed); empty otherwise.
std::string closestName(const std::string& word, const std::vector<std::string>& candidates);

// Prints the error on stderr for `app` (the whole command line, `argv` as given to parse) and
// returns the exit code.
int reportParseError(const CLI::App& app, const CLI::ParseError& error, int argc, char** argv);

}  // namespace woven
