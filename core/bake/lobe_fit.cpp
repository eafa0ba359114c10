#include "lobe_fit.h"

#include <algorithm>
#include <cmath>

#include "math_constants.h"

namespace woven {

namespace {

double pow5(double x) { return (x * x) * (x * x) * x; }

// The bi-hemispherical albedo of glTF's diffuse term (1 - F(v.h)) / pi with F0 = 0, F90 = 1,
// by the midpoint rule in (cos theta_o, cos theta_i, phi): v.h = sqrt((1 + wo.wi) / 2) is smooth,
// so 64 nodes a dimension give it to far better than 1e-4.
double gltfDiffuseAlbedo() {
    constexpr int n = 64;
    double sum = 0.0;
    for (int a = 0; a < n; ++a) {
        const double co = (a + 0.5) / n, so = std::sqrt(1.0 - co * co);
        for (int b = 0; b < n; ++b) {
            const double ci = (b + 0.5) / n, si = std::sqrt(1.0 - ci * ci);
            for (int c = 0; c < n; ++c) {
                const double phi = kPiDouble * (c + 0.5) / n;  // symmetric in phi: half the circle, twice
                const double vh = std::sqrt(std::max(0.0, 0.5 * (1.0 + co * ci + so * si * std::cos(phi))));
                sum += (1.0 - pow5(1.0 - vh)) * co * ci;
            }
        }
    }
    // Integral over d omega_o d omega_i = d cos_o d cos_i d phi_o d phi_i: 2 pi (phi_o) x 2 pi
    // (relative phi, here 2 x pi / n per node) x (1 / n)^2; f = (1 - F) / pi, then / pi.
    return sum * (2.0 * kPiDouble) * (2.0 * kPiDouble / n) / (double(n) * n) / (kPiDouble * kPiDouble);
}

// A-S's at rs = 0: 28 R_d / (23 pi) g(cos_o) g(cos_i), g(c) = 1 - (1 - c / 2)^5, whose integral
// int_0^1 g(c) c dc = 1/2 - 4 (63/384 - 127/896) is exact.
double ashikhminShirleyDiffuseAlbedo() {
    const double g = 0.5 - 4.0 * (63.0 / 384.0 - 127.0 / 896.0);
    const double hemisphere = 2.0 * kPiDouble * g;
    return 28.0 / (23.0 * kPiDouble) * hemisphere * hemisphere / kPiDouble;
}

}  // namespace

float ggxAlphaForExponent(float e) { return std::min(1.0f, std::sqrt(2.0f / (std::max(e, 0.0f) + 2.0f))); }

float diffuseScale() {
    static const float k = float(ashikhminShirleyDiffuseAlbedo() / gltfDiffuseAlbedo());
    return k;
}

float iorForF0(float rs) {
    const float r = std::sqrt(std::clamp(rs, 0.0f, 0.999f));
    return (1.0f + r) / (1.0f - r);
}

}  // namespace woven
