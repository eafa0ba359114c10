#pragma once
// A number in a message as people write it: "1e+300", "2.5", "0.001" (printf's %g), never the
// 309 digits std::to_string gives the largest double.
#include <string>

namespace woven {

std::string shortNumber(double value);

}  // namespace woven
