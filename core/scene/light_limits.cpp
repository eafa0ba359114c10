#include "light_limits.h"

#include <cmath>
#include <sstream>

namespace woven {

std::string lightValueProblem(const glm::vec3& value) {
    for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(value[c])) return "is not finite";
        if (value[c] < 0.0f) return "is negative";
        if (value[c] > kMaxLightValue) {
            std::ostringstream s;
            s << "is " << value[c] << ", more than woven's limit of " << kMaxLightValue
              << " (W/sr, W/m^2 or W/(m^2 sr): no real light comes near it)";
            return s.str();
        }
    }
    return "";
}

}  // namespace woven
