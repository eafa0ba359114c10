#pragma once
// The fit's local optimiser: NLopt's BOBYQA (Powell 2009, bound-constrained, derivative-free) over
// the unit box, stopped by a budget or a cancel, keeping the best point it met.
#include <functional>
#include <vector>

namespace woven {

using Objective = std::function<double(const std::vector<double>&)>;

// Minimises `objective` from x within [0, 1]^n, at most `evaluations` of it (0: until it
// converges or `stop` says so, asked before each); x becomes the best point it met. Returns the
// evaluations it took.
int minimiseInUnitBox(std::vector<double>& x, const Objective& objective, int evaluations,
                      const std::function<bool()>& stop);

}  // namespace woven
