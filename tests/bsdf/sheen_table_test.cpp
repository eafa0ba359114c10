// The sheen's directional albedo table (SheenLobe::albedoTable, integrated once by the midpoint
// rule) against a finer, independent integral of the reference Charlie sheen of
// reference_gltf_brdf.h, at a grid of its entries, and albedo()'s bilinear lookup between them.
//
// Thresholds (deterministic: no randomness here). Entries: 1 % + 1e-4. The table's midpoint rule
// (96 x 48 cells) is worst at the grazing end of the sharpest sheen, 0.7 % (printed); a mistake
// in building it (the phi fold, the cosine weight, the roughness of a row) moves entries by
// tens of percent. Lookups between entries: bilinear in cos theta with steps of 1/31 cannot
// follow E's steep rise below cos theta ~ 0.1 (the Lambda fit's mu^0.2 term), where it is off by
// up to 0.06 (printed); above that, 0.01 holds.
//
// E exceeds 1 at grazing angles for sheen roughness below ~0.2 (2.9 at cos theta = 0.001 and
// roughness 0.07): Conty-Kulla's fitted Lambda stays finite at the horizon, where masking should
// grow like 1 / cos. This is the model of KHR_materials_sheen, not the table; the layering
// clamps 1 - max(sheenColor) E at 0 there, and GltfEnergy reports what it does to the albedo.
//
// The reference integral: E(mu_o) = 2 int_0^pi int_0^1 f(wo, wi) mu_i dmu_i dphi (f is even in
// phi), composite 8-point Gauss-Legendre in both variables, with mu_i = t^4: the Conty-Kulla
// Lambda has a term in mu^0.2, whose unbounded derivative at mu = 0 the substitution smooths
// (t^0.8), and it crowds the nodes towards the horizon where a smooth sheen peaks. Its own
// error is measured by halving the panels (printed) and is far below the table's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "bsdf_test_util.h"
#include "sheen_lobe.h"

namespace woven {
namespace {

using namespace woven::test;

constexpr int kN = SheenLobe::kAlbedoTableSize;

double referenceAlbedo(double cosO, double sheenRoughness, int panels) {
    const glm::dvec3 wo(std::sqrt(1.0 - cosO * cosO), 0.0, cosO);
    const auto overMu = [&](double phi) {
        return compositeGauss([&](double t) {
            const double t2 = t * t, mu = t2 * t2;  // mu = t^4, dmu = 4 t^3 dt
            const double s = std::sqrt(std::max(0.0, 1.0 - mu * mu));
            const glm::dvec3 wi(s * std::cos(phi), s * std::sin(phi), mu);
            return gltfref::sheenBrdf(sheenRoughness, wo, wi) * mu * 4.0 * t2 * t;
        }, 0.0, 1.0, panels);
    };
    return 2.0 * compositeGauss(overMu, 0.0, gltfref::kPi, panels / 2);
}

// The table's grid: roughness of row r and cos theta of column m, as sheen_lobe.cpp builds it.
double rowRoughness(int r) { return std::max(double(r) / (kN - 1), gltfref::kMinSheenRoughness); }
double columnCos(int m) { return std::max(double(m) / (kN - 1), 1e-3); }

const int kRows[] = {0, 3, 6, 10, 16, 24, 31};
const int kColumns[] = {0, 1, 2, 4, 8, 16, 31};
constexpr int kPanels = 32;

TEST(SheenAlbedoTable, EntriesMatchAFinerIntegral) {
    const auto& table = SheenLobe::albedoTable();
    double worstAbs = 0.0, worstRel = 0.0, worstQuadrature = 0.0;
    int worstRow = 0, worstColumn = 0;
    std::printf("[ sheen E ] table entry / finer integral, rows: sheen roughness, columns: cos theta\n");
    std::printf("[ sheen E ] %6s", "r \\ mu");
    for (int m : kColumns) std::printf(" %15.3f", columnCos(m));
    std::printf("\n");
    for (int r : kRows) {
        std::printf("[ sheen E ] %6.3f", rowRoughness(r));
        for (int m : kColumns) {
            const double fine = referenceAlbedo(columnCos(m), rowRoughness(r), kPanels);
            if (r == 0 || m == 0) {  // the quadrature's own error where the integrand is hardest
                const double coarse = referenceAlbedo(columnCos(m), rowRoughness(r), kPanels / 2);
                worstQuadrature = std::max(worstQuadrature, std::abs(fine - coarse));
            }
            const double entry = table[size_t(r) * kN + m];
            std::printf(" %7.4f/%7.4f", entry, fine);
            const double err = std::abs(entry - fine);
            EXPECT_LE(err, 0.01 * fine + 1e-4) << "roughness " << rowRoughness(r) << " cos " << columnCos(m);
            if (fine > 1e-3) worstRel = std::max(worstRel, err / fine);
            if (err > worstAbs) {
                worstAbs = err;
                worstRow = r;
                worstColumn = m;
            }
        }
        std::printf("\n");
    }
    std::printf("[ sheen E ] worst table error %.4f (absolute) at roughness %.3f, cos theta %.3f; worst relative "
                "%.4f (where E > 1e-3); the finer integral's own error (panels halved) < %.1e\n",
                worstAbs, rowRoughness(worstRow), columnCos(worstColumn), worstRel, worstQuadrature);
    EXPECT_LT(worstQuadrature, 1e-5);
}

TEST(SheenAlbedoTable, LookupBetweenEntries) {
    double worstAbs = 0.0, worstRel = 0.0;
    std::printf("[ sheen E ] albedo() between entries / finer integral\n");
    for (double r : {0.085, 0.15, 0.25, 0.4, 0.6, 0.9})
        for (double mu : {0.016, 0.048, 0.1, 0.2, 0.35, 0.6, 0.9}) {
            const double fine = referenceAlbedo(mu, r, kPanels);
            const double lookup = SheenLobe(glm::vec3(1.0f), float(r)).albedo(float(mu));
            const double err = std::abs(lookup - fine);
            worstAbs = std::max(worstAbs, err);
            if (fine > 0.01) worstRel = std::max(worstRel, err / fine);
            if (err > 0.01) std::printf("[ sheen E ]   r %.3f mu %.3f: %.4f / %.4f\n", r, mu, lookup, fine);
            EXPECT_LT(err, mu >= 0.1 ? 0.01 : 0.08) << "roughness " << r << " cos " << mu;
        }
    std::printf("[ sheen E ] lookup: worst absolute error %.4f, relative %.3f (where E > 0.01)\n", worstAbs, worstRel);
}

}  // namespace
}  // namespace woven
