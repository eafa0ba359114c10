#include "weave_coverage.h"

#include <algorithm>
#include <numeric>

namespace woven {

WeaveCoverage weaveCoverage(const Weave& weave, bool backSide) {
    const WeavePattern& pattern = weave.pattern(backSide);
    const ThreadLayout &ends = weave.warp(), &picks = weave.weft();
    const long columns = std::min(std::lcm(long(pattern.width()), long(ends.period())), kMaxCoverageSide);
    const long rows = std::min(std::lcm(long(pattern.height()), long(picks.period())), kMaxCoverageSide);
    double weftArea = 0.0, warpArea = 0.0, totalArea = 0.0;
    double weftInWarpCells = 0.0, warpInWarpCells = 0.0, warpCellArea = 0.0;
    std::vector<double> yarnArea(size_t(weave.yarnCount()), 0.0);
    for (long V = 0; V < rows; ++V) {
        const int pick = int(V % picks.period());
        const double height = picks.spaced() ? picks.width(pick) : 1.0;
        const int weftYarn = picks.yarn(pick);
        const float weftWidth = weave.yarn(weftYarn).width();
        for (long U = 0; U < columns; ++U) {
            const int end = int(U % ends.period());
            const double area = height * (ends.spaced() ? ends.width(end) : 1.0);
            const int warpYarn = ends.yarn(end);
            const float warpWidth = weave.yarn(warpYarn).width();
            // yarnAt's rule: the top yarn covers its width across the cell, the crossing yarn
            // its own width of the rest.
            const bool warpOnTop = pattern.top(U, V) == YarnType::Warp;
            const double weft = area * (warpOnTop ? (1.0 - warpWidth) * weftWidth : weftWidth);
            const double warp = area * (warpOnTop ? warpWidth : (1.0 - weftWidth) * warpWidth);
            weftArea += weft;
            warpArea += warp;
            if (warpOnTop) {
                weftInWarpCells += weft;
                warpInWarpCells += warp;
                warpCellArea += area;
            }
            yarnArea[size_t(weftYarn)] += weft;
            yarnArea[size_t(warpYarn)] += warp;
            totalArea += area;
        }
    }
    WeaveCoverage c{float(weftArea / totalArea), float(warpArea / totalArea), {}, float(weftInWarpCells / totalArea),
                    float(warpInWarpCells / totalArea), float(warpCellArea / totalArea)};
    for (double a : yarnArea) c.yarns.push_back(float(a / totalArea));
    return c;
}

}  // namespace woven
