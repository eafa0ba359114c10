#pragma once
// Which woven this is: the project's version and the git commit the build was configured from,
// for `woven --version` and bug reports. Both are baked in when CMake configures (app/version.cpp.in).
namespace woven {

const char* wovenVersion();  // "0.1.0"
const char* wovenCommit();   // "3124910a1b2c", or "unknown" outside a git checkout

}  // namespace woven
