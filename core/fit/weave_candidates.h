#pragma once
// The weaves the fit tries (docs/FIT.md): plain, the 2/1, 3/1 and 2/2 twills and the 5- and
// 8-end satins, each weft-faced and warp-faced and in both directions (a twill's k = 1 and
// k = i + j - 1 run its diagonal the two ways), as (i, j, k) of MODEL.md section 1.
#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace woven {

struct WeaveCandidate {
    glm::ivec3 pattern;
    const char* name;  // "plain", "twill", "satin"
};
const std::vector<WeaveCandidate>& weaveCandidates();

// "twill 1/3 (1, 3, 1)": the class, weft over / warp over, and the pattern.
std::string describeWeave(const glm::ivec3& pattern);

}  // namespace woven
