#pragma once
// Piecewise-constant densities on [0, 1] and [0, 1]^2, sampled by inverting their CDFs (pbrt-v3's
// Distribution1D and Distribution2D). They choose lights by power and directions of an
// environment image by brightness.
#include <glm/glm.hpp>
#include <vector>

namespace woven {

class PiecewiseConstant1D {
public:
    // `func` must be non-negative; where it is all zero the density is uniform.
    explicit PiecewiseConstant1D(const std::vector<float>& func);

    int size() const { return int(cdf_.size()) - 1; }
    float integral() const { return integral_; }  // of the function as given, over [0, 1]

    // A continuous sample in [0, 1) with its density; `offset` receives the piece.
    float sampleContinuous(float u, float* pdf, int* offset = nullptr) const;
    // A piece chosen with probability func[i] / sum; `uRemapped` is u rescaled within it.
    int sampleDiscrete(float u, float* pmf, float* uRemapped = nullptr) const;
    float discretePmf(int index) const;
    float pdf(float x) const;  // density of sampleContinuous at x in [0, 1]

private:
    std::vector<float> cdf_;  // size() + 1 entries from 0 to 1
    float integral_;
};

class PiecewiseConstant2D {
public:
    // func[v * nu + u], nu columns by nv rows: v picks a row by its marginal, then u within it.
    PiecewiseConstant2D(const std::vector<float>& func, int nu, int nv);

    glm::vec2 sample(const glm::vec2& u, float* pdf) const;
    float pdf(const glm::vec2& p) const;  // density over [0, 1]^2

private:
    std::vector<PiecewiseConstant1D> conditional_;  // one per row
    PiecewiseConstant1D marginal_;
};

}  // namespace woven
