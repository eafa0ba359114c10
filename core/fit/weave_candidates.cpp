#include "weave_candidates.h"

namespace woven {

const std::vector<WeaveCandidate>& weaveCandidates() {
    static const std::vector<WeaveCandidate> list{
        {{1, 1, 1}, "plain"},
        {{1, 2, 1}, "twill"}, {{1, 2, 2}, "twill"}, {{2, 1, 1}, "twill"}, {{2, 1, 2}, "twill"},
        {{1, 3, 1}, "twill"}, {{1, 3, 3}, "twill"}, {{3, 1, 1}, "twill"}, {{3, 1, 3}, "twill"},
        {{2, 2, 1}, "twill"}, {{2, 2, 3}, "twill"},
        {{4, 1, 2}, "satin"}, {{4, 1, 3}, "satin"}, {{1, 4, 2}, "satin"}, {{1, 4, 3}, "satin"},
        {{7, 1, 3}, "satin"}, {{7, 1, 5}, "satin"}, {{1, 7, 3}, "satin"}, {{1, 7, 5}, "satin"},
    };
    return list;
}

std::string describeWeave(const glm::ivec3& p) {
    std::string name = "weave";
    for (const WeaveCandidate& c : weaveCandidates())
        if (c.pattern == p) name = c.name;
    const std::string ijk = "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z) + ")";
    if (name == "plain") return "plain " + ijk;
    return name + " " + std::to_string(p.x) + "/" + std::to_string(p.y) + " " + ijk;
}

}  // namespace woven
