#pragma once
// Tools for checking a sampler against its density over the directions of a hemisphere:
// two parameterisations of the directions by the unit square (cells for histograms, points for
// quadrature), per-cell integrals, and Pearson's chi-square test with a p-value.
#include <glm/glm.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace woven::test {

// A parameterisation of directions wi (local frame, z = normal) by [0, 1)^2.
class DirectionDomain {
public:
    virtual ~DirectionDomain() = default;
    // The square point of a direction with wi.z > 0.
    virtual glm::dvec2 toSquare(const glm::dvec3& wi) const = 0;
    // The direction at square point p and the density |d omega / dp|; false where p maps to none.
    virtual bool fromSquare(const glm::dvec2& p, glm::dvec3& wi, double& jacobian) const = 0;
};

// (cos theta, phi / 2 pi): pbrt's and Mitsuba's binning, uniform in solid angle.
std::unique_ptr<DirectionDomain> sphericalDomain();

// The half vector h of (wo, wi) in slope space (h.x / h.z, h.y / h.z), each slope multiplied by a
// scale, then squeezed into (0, 1): linearly near 0, logarithmically in the tails, atan at the
// end. With scales sqrt(e + 1) a lobe of exponents (e_x, e_y) is about one unit wide in the
// scaled slopes, so it spans many cells for any exponent up to 1e5, while the diffuse part
// still spreads over the outer cells; a (cos theta, phi) grid would put a lobe of e = 1e4
// (about 0.01 rad wide) into one cell and test nothing.
std::unique_ptr<DirectionDomain> halfVectorDomain(const glm::dvec3& wo, double scaleX, double scaleY);

// Integral of g(wi) over each cell of a res x res grid of the domain, row-major with x fastest:
// Gauss-Legendre of the given order, each cell split into quarters (up to maxDepth times) until
// the quarters agree with the whole to a relative 1e-4 (absolute 1e-9).
std::vector<double> integrateCells(const DirectionDomain& domain, const std::function<double(const glm::dvec3&)>& g,
                                   int res, int maxDepth = 4, int order = 5);

// The integral of g over the whole domain.
double integrateDomain(const DirectionDomain& domain, const std::function<double(const glm::dvec3&)>& g,
                       int res = 64, int maxDepth = 4, int order = 5);

struct ChiSquareOutcome {
    bool passed;
    double pValue;
    double statistic;
    int dof;
    std::string message;  // why it failed, or the figures
};

// Pearson's test of observed cell counts against expected ones. Cells whose expected count is
// below 5 are pooled (smallest first) until the pool reaches 5, as in pbrt-v4's chi2test. A cell
// with observed samples but an expected count of 0 goes into the pool too: numerical
// integration can miss a sliver of support cut by the horizon; whether a sample lies in the
// support is for the caller to check pointwise (pdf(wi) > 0).
ChiSquareOutcome chiSquareTest(const std::vector<double>& observed, const std::vector<double>& expected,
                               double significance);

// Upper tail Q(dof / 2, x / 2) of the chi-square distribution.
double chiSquarePValue(double statistic, int dof);

// Gauss-Legendre nodes and weights of the given order on [0, 1].
void gaussLegendre(int order, std::vector<double>& nodes, std::vector<double>& weights);

}  // namespace woven::test
