#pragma once
// The check of an option that takes one of a few names. CLI11's IsMember answered in its own
// notation ("foo not in {path,bdpt,auto}", "{} not in {on,off}").
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace woven {

// One of `names`, as written: "'foo' is not one of path, bdpt or auto".
CLI::Validator oneOf(const std::vector<std::string>& names);

}  // namespace woven
