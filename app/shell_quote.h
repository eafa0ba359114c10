#pragma once
// Words for a POSIX shell: what `woven submit` writes into job scripts and prints as commands
// must reach the program as the same bytes, whatever spaces, quotes or $ a path or a JSON value
// holds.
#include <string>
#include <vector>

namespace woven {

// `word` as the shell reads it back: unchanged when it holds only characters that are never
// special, else in single quotes (a ' inside becomes '\'').
std::string shellQuote(const std::string& word);

// The words quoted and joined by spaces: a command line.
std::string shellCommand(const std::vector<std::string>& words);

}  // namespace woven
