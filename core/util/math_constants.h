#pragma once
// The constants of the renderer's formulas, defined once.
namespace woven {

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr double kPiDouble = 3.14159265358979323846;

}  // namespace woven
