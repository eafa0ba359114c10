#include "direction_domain.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "reference_brdf.h"

namespace woven::test {

namespace {

class Spherical : public DirectionDomain {
public:
    glm::dvec2 toSquare(const glm::dvec3& wi) const override {
        double phi = std::atan2(wi.y, wi.x);
        if (phi < 0.0) phi += 2.0 * kPi;
        return {std::clamp(wi.z, 0.0, 1.0), phi / (2.0 * kPi)};
    }
    bool fromSquare(const glm::dvec2& p, glm::dvec3& wi, double& jacobian) const override {
        const double z = p.x, phi = 2.0 * kPi * p.y, r = std::sqrt(std::max(0.0, 1.0 - z * z));
        wi = {r * std::cos(phi), r * std::sin(phi), z};
        jacobian = 2.0 * kPi;
        return true;
    }
};

class HalfVectorSlopes : public DirectionDomain {
public:
    HalfVectorSlopes(const glm::dvec3& wo, double sx, double sy) : wo_(glm::normalize(wo)), sx_(sx), sy_(sy) {}

    glm::dvec2 toSquare(const glm::dvec3& wi) const override {
        const glm::dvec3 h = glm::normalize(wo_ + wi);
        return {squeeze(h.x / h.z * sx_), squeeze(h.y / h.z * sy_)};
    }
    bool fromSquare(const glm::dvec2& p, glm::dvec3& wi, double& jacobian) const override {
        double dx, dy;
        const double slopeX = unsqueeze(p.x, dx) / sx_, slopeY = unsqueeze(p.y, dy) / sy_;
        const double r2 = 1.0 + slopeX * slopeX + slopeY * slopeY;
        if (!std::isfinite(r2)) return false;
        const glm::dvec3 h = glm::dvec3(slopeX, slopeY, 1.0) / std::sqrt(r2);
        const double oh = glm::dot(wo_, h);
        if (!(oh > 0.0)) return false;
        wi = 2.0 * oh * h - wo_;
        // d omega_i = 4 (wo.h) d omega_h and d omega_h = d slopes / r2^(3/2).
        jacobian = 4.0 * oh / (r2 * std::sqrt(r2)) * (dx / sx_) * (dy / sy_);
        return std::isfinite(jacobian);
    }

private:
    // Scaled slope -> (0, 1): linear near 0 (the lobe), logarithmic beyond (so that a broad
    // diffuse part still spreads over many cells when the scale is large), then atan.
    static constexpr double kTail = 2.0;
    static double squeeze(double scaledSlope) { return 0.5 + std::atan(std::asinh(scaledSlope) / kTail) / kPi; }
    // The inverse, with its derivative d(scaled slope)/dx.
    static double unsqueeze(double x, double& derivative) {
        const double a = std::tan(kPi * (x - 0.5));
        derivative = kPi * (1.0 + a * a) * kTail * std::cosh(kTail * a);
        return std::sinh(kTail * a);
    }

    glm::dvec3 wo_;
    double sx_, sy_;
};


// Regularised lower incomplete gamma P(a, x) by series, upper Q(a, x) by continued fraction
// (Numerical Recipes, 6.2).
double gammaQ(double a, double x) {
    if (x <= 0.0) return 1.0;
    const double lnPrefix = -x + a * std::log(x) - std::lgamma(a);
    if (x < a + 1.0) {
        double sum = 1.0 / a, term = sum, ap = a;
        for (int n = 0; n < 100000; ++n) {
            ap += 1.0;
            term *= x / ap;
            sum += term;
            if (std::fabs(term) < std::fabs(sum) * 1e-15) break;
        }
        return 1.0 - sum * std::exp(lnPrefix);
    }
    double b = x + 1.0 - a, c = 1e300, d = 1.0 / b, h = d;
    for (int i = 1; i < 100000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::fabs(d) < 1e-300) d = 1e-300;
        c = b + an / c;
        if (std::fabs(c) < 1e-300) c = 1e-300;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::fabs(delta - 1.0) < 1e-15) break;
    }
    return std::exp(lnPrefix) * h;
}

}  // namespace

std::unique_ptr<DirectionDomain> sphericalDomain() { return std::make_unique<Spherical>(); }

std::unique_ptr<DirectionDomain> halfVectorDomain(const glm::dvec3& wo, double scaleX, double scaleY) {
    return std::make_unique<HalfVectorSlopes>(wo, scaleX, scaleY);
}

namespace {

// Gauss-Legendre over the square [x0, x0 + size] x [y0, y0 + size].
double integrateSquare(const DirectionDomain& domain, const std::function<double(const glm::dvec3&)>& g,
                       double x0, double y0, double size, const std::vector<double>& nodes,
                       const std::vector<double>& weights) {
    double sum = 0.0;
    for (size_t a = 0; a < nodes.size(); ++a)
        for (size_t b = 0; b < nodes.size(); ++b) {
            glm::dvec3 wi;
            double jacobian;
            if (!domain.fromSquare({x0 + nodes[a] * size, y0 + nodes[b] * size}, wi, jacobian)) continue;
            sum += weights[a] * weights[b] * jacobian * g(wi);
        }
    return sum * size * size;
}

// Splits a square into quarters until the quarters agree with the whole: the pdf is smooth
// except where the horizon cuts it off, and there a fixed rule would misjudge thin slivers.
double integrateAdaptive(const DirectionDomain& domain, const std::function<double(const glm::dvec3&)>& g,
                         double x0, double y0, double size, double whole, int depth,
                         const std::vector<double>& nodes, const std::vector<double>& weights) {
    const double half = 0.5 * size;
    double quarters[4], sum = 0.0;
    for (int q = 0; q < 4; ++q) {
        quarters[q] = integrateSquare(domain, g, x0 + (q & 1) * half, y0 + (q >> 1) * half, half, nodes, weights);
        sum += quarters[q];
    }
    if (depth == 0 || std::fabs(sum - whole) <= std::max(1e-9, 1e-4 * std::fabs(sum))) return sum;
    double refined = 0.0;
    for (int q = 0; q < 4; ++q)
        refined += integrateAdaptive(domain, g, x0 + (q & 1) * half, y0 + (q >> 1) * half, half, quarters[q],
                                     depth - 1, nodes, weights);
    return refined;
}

}  // namespace

std::vector<double> integrateCells(const DirectionDomain& domain, const std::function<double(const glm::dvec3&)>& g,
                                   int res, int maxDepth, int order) {
    std::vector<double> nodes, weights;
    gaussLegendre(order, nodes, weights);
    std::vector<double> cells(size_t(res) * res, 0.0);
    const double size = 1.0 / res;
    for (int cy = 0; cy < res; ++cy)
        for (int cx = 0; cx < res; ++cx) {
            const double whole = integrateSquare(domain, g, cx * size, cy * size, size, nodes, weights);
            cells[size_t(cy) * res + cx] =
                integrateAdaptive(domain, g, cx * size, cy * size, size, whole, maxDepth, nodes, weights);
        }
    return cells;
}

double integrateDomain(const DirectionDomain& domain, const std::function<double(const glm::dvec3&)>& g, int res,
                       int maxDepth, int order) {
    const std::vector<double> cells = integrateCells(domain, g, res, maxDepth, order);
    return std::accumulate(cells.begin(), cells.end(), 0.0);
}

double chiSquarePValue(double statistic, int dof) { return gammaQ(0.5 * dof, 0.5 * statistic); }

ChiSquareOutcome chiSquareTest(const std::vector<double>& observed, const std::vector<double>& expected,
                               double significance) {
    std::ostringstream msg;
    std::vector<size_t> order(expected.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return expected[a] < expected[b]; });

    double pooledObserved = 0.0, pooledExpected = 0.0, statistic = 0.0;
    int cells = 0;
    for (size_t idx : order) {
        if (expected[idx] < 5.0 && pooledExpected < 5.0) {
            pooledObserved += observed[idx];
            pooledExpected += expected[idx];
            continue;
        }
        const double diff = observed[idx] - expected[idx];
        statistic += diff * diff / expected[idx];
        ++cells;
    }
    if (pooledExpected > 0.0) {
        const double diff = pooledObserved - pooledExpected;
        statistic += diff * diff / pooledExpected;
        ++cells;
    }
    const int dof = cells - 1;
    if (dof < 1) return {false, 0.0, statistic, dof, "fewer than two cells with expected counts"};
    const double p = chiSquarePValue(statistic, dof);
    msg << "chi2 = " << statistic << ", dof = " << dof << ", p = " << p << ", significance = " << significance;
    return {p >= significance, p, statistic, dof, msg.str()};
}

void gaussLegendre(int order, std::vector<double>& nodes, std::vector<double>& weights) {
    nodes.resize(order);
    weights.resize(order);
    for (int i = 0; i < order; ++i) {
        double x = std::cos(kPi * (i + 0.75) / (order + 0.5)), dp = 0.0;
        for (int iter = 0; iter < 100; ++iter) {  // Newton on P_order
            double p0 = 1.0, p1 = x;
            for (int k = 2; k <= order; ++k) {
                const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = order * (x * p1 - p0) / (x * x - 1.0);
            const double dx = p1 / dp;
            x -= dx;
            if (std::fabs(dx) < 1e-15) break;
        }
        nodes[i] = 0.5 * (1.0 - x);
        weights[i] = 1.0 / ((1.0 - x * x) * dp * dp);  // 2 / ((1 - x^2) P'^2), halved for [0, 1]
    }
}

}  // namespace woven::test
