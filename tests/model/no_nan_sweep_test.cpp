// MODEL.md section 5: no NaN or Inf anywhere. About two million queries, random and hard-case
// (huge and negative uv, degenerate dp/du and dp/dv, grazing and opposite directions, extreme
// exponents, yarn edges at full curvature, tiny widths, full crimp and noise, i + j = 1 and 64,
// the back side), each through WovenMaterial::shade and the BSDF's eval, pdf and sample.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "sampling.h"
#include "woven_material.h"

namespace woven {
namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Float frames built from normalised float vectors are orthonormal to a few ulps; 1e-3 catches
// any frame that is really skewed or unnormalised.
bool orthonormal(const Frame& f) {
    const float tol = 1e-3f;
    return std::abs(glm::length(f.x) - 1) < tol && std::abs(glm::length(f.y) - 1) < tol &&
           std::abs(glm::length(f.z) - 1) < tol && std::abs(glm::dot(f.x, f.y)) < tol &&
           std::abs(glm::dot(f.y, f.z)) < tol && std::abs(glm::dot(f.z, f.x)) < tol;
}

std::vector<WovenParams> hardMaterials() {
    std::vector<WovenParams> all;
    auto add = [&](auto change) {
        WovenParams p;
        change(p);
        all.push_back(p);
    };
    add([](WovenParams&) {});
    add([](WovenParams& p) { p.ex = p.ey = p.warp_ex = p.warp_ey = 0.0f; });
    add([](WovenParams& p) { p.ex = p.ey = p.warp_ex = p.warp_ey = 1e5f; });
    add([](WovenParams& p) { p.ex = 1e5f; p.ey = 10.0f; p.warp_ex = 10.0f; p.warp_ey = 1e5f; });  // ratio 1e4
    add([](WovenParams& p) { p.ex = 1e4f; p.ey = 0.0f; p.warp_ex = 0.0f; p.warp_ey = 1e5f; });
    add([](WovenParams& p) { p.cy = 1.0f; p.crimp = 1.0f; p.noise = 1.0f; p.pattern = {9, 1, 3}; });
    add([](WovenParams& p) { p.cy = 1.0f; p.yarn_width = p.warp_width = 1e-3f; p.backing = 1; p.backing_color = glm::vec3(1.0f); });
    add([](WovenParams& p) { p.cy = 1.0f; p.yarn_width = 1e-3f; p.warp_width = 1.0f; p.crimp = 1.0f; });
    add([](WovenParams& p) { p.pattern = {1, 0, 0}; p.cy = 1.0f; p.crimp = 1.0f; p.noise = 1.0f; });
    add([](WovenParams& p) { p.pattern = {0, 1, 5}; p.cy = 1.0f; p.crimp = 1.0f; p.noise = 1.0f; p.noise_scale = 100.0f; });
    add([](WovenParams& p) { p.pattern = {63, 1, 7}; p.cy = 1.0f; p.crimp = 1.0f; p.ex = 1e5f; p.ey = 0.0f; });
    add([](WovenParams& p) { p.pattern = {32, 32, 70}; p.cy = 0.9f; p.crimp = 0.7f; p.noise = 0.5f; p.noise_scale = 1e-3f; });
    add([](WovenParams& p) { p.repeat = {1e6f, 1e-6f}; p.cy = 1.0f; p.noise = 1.0f; p.crimp = 1.0f; });
    add([](WovenParams& p) { p.tile = {"-||-", "|--|", "-|--"}; p.cy = 1.0f; p.crimp = 1.0f; p.rs = 1.0f; p.weft_color = glm::vec3(1.0f); });
    // Per-thread lists (MODEL.md section 6): spacing from 1e-6 to 1e6 of the mean (the lookup's
    // worst case), yarn types at the range limits, colours 0 and 1.
    add([](WovenParams& p) {
        YarnSpec extreme, flat;
        extreme.value = {1e5f, 0.0f, 1.0f, 1e-3f, 1.0f, 1.0f};
        extreme.set.fill(true);
        flat.value[kYarnCy] = 0.0f;
        flat.set[kYarnCy] = true;
        p.yarns = {extreme, flat};
        p.warp_yarns = {0, 1, 1};
        p.weft_yarns = {1, 0};
        p.warp_colors = {glm::vec3(0.0f), glm::vec3(1.0f)};
        p.warp_spacing = {1e-6f, 1e6f, 1.0f};
        p.weft_spacing = {1e6f, 1e-6f};
        p.crimp = 1.0f;
        p.pattern = {9, 1, 3};
    });
    return all;
}

class Sweep {
public:
    explicit Sweep(uint64_t seed) : rng_(seed) {}

    glm::vec3 unit() {
        const float z = 1.0f - 2.0f * rng_.uniform(), phi = 6.2831853f * rng_.uniform();
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        return {r * std::cos(phi), r * std::sin(phi), z};
    }
    int pick(int n) { return std::min(n - 1, int(rng_.uniform() * n)); }

    // uv: random small, random huge (|u|, |v| up to 1e6, negative too), on element borders,
    // and exactly on a yarn edge |x| = 1 for the material's widths.
    glm::dvec2 uv(const WovenParams& p) {
        auto coord = [&](float repeat, float width) -> double {
            const double element = std::floor((rng_.uniform() - 0.5) * 2e3);
            switch (pick(5)) {
                case 0: return (rng_.uniform() - 0.5) * 20.0;
                case 1: return (double(rng_.uniform()) - 0.5) * 2e6;
                case 2: return element / repeat;
                case 3: return (element + 0.5 + 0.5 * (pick(2) ? width : -width)) / repeat;
                default: return (element + rng_.uniform()) / repeat;
            }
        };
        const float w = pick(2) ? p.yarn_width : p.warp_width;
        return {coord(p.repeat.x, w), coord(p.repeat.y, w)};
    }

    ShadingInput hit(const WovenParams& p) {
        ShadingInput in;
        in.uv = uv(p);
        in.ns = unit();
        auto tangent = [&]() -> glm::vec3 {
            switch (pick(5)) {
                case 0: return glm::vec3(0.0f);                     // dp/du = 0
                case 1: return in.ns * (rng_.uniform() * 4 - 2);    // parallel to ns
                case 2: return unit() * 1e-20f;                     // vanishingly small
                default: return unit() * (rng_.uniform() * 10);
            }
        };
        in.dpdu = tangent();
        in.dpdv = pick(4) ? tangent() : in.dpdu;  // sometimes dp/du = dp/dv
        in.backSide = pick(2);
        return in;
    }

    // Directions relative to the shading normal: random, grazing, mirrored and opposite pairs
    // (h.k -> 0), identical, exactly along the normal.
    std::pair<glm::vec3, glm::vec3> directions(const glm::vec3& n) {
        const glm::vec3 t = glm::normalize(glm::cross(n, unit()) + 1e-30f);
        // A random direction in the plane of n, tipped by 1e-6 to the given side.
        auto grazing = [&](float side) {
            const glm::vec3 r = unit();
            return glm::normalize(r - glm::dot(r, n) * n + side * 1e-6f * n);
        };
        glm::vec3 wo = unit(), wi = unit();
        switch (pick(8)) {
            case 0: break;
            case 1: wo = glm::normalize(t + 1e-7f * n); break;
            case 2: wi = glm::normalize(t + 1e-7f * n); wo = glm::normalize(-t + 1e-7f * n); break;
            case 3: wi = -wo; break;
            case 4: wi = glm::normalize(-wo + 1e-6f * unit()); break;
            case 5: wi = wo; break;
            case 6: wo = n; wi = pick(2) ? n : -n; break;
            default: wo = grazing(1.0f); wi = grazing(-1.0f); break;
        }
        if (!finite(wo) || glm::length(wo) < 0.5f) wo = n;
        if (!finite(wi) || glm::length(wi) < 0.5f) wi = n;
        return {wo, wi};
    }

    float u() { return pick(10) ? rng_.uniform() : (pick(2) ? 0.0f : 0x1.fffffep-1f); }

private:
    Rng rng_;
};

std::string describe(const ShadingInput& in, const glm::vec3& wo, const glm::vec3& wi) {
    std::ostringstream s;
    s.precision(9);
    s << "uv (" << in.uv.x << ", " << in.uv.y << ") ns (" << in.ns.x << ", " << in.ns.y << ", " << in.ns.z
      << ") dpdu (" << in.dpdu.x << ", " << in.dpdu.y << ", " << in.dpdu.z << ") dpdv (" << in.dpdv.x << ", "
      << in.dpdv.y << ", " << in.dpdv.z << ") back " << in.backSide << " wo (" << wo.x << ", " << wo.y << ", "
      << wo.z << ") wi (" << wi.x << ", " << wi.y << ", " << wi.z << ")";
    return s.str();
}

TEST(NoNanSweep, TwoMillionHardQueries) {
    const auto materials = hardMaterials();
    const int queriesPerMaterial = 2'000'000 / int(materials.size());
    int failures = 0;
    long shaded = 0, sampled = 0;
    for (size_t m = 0; m < materials.size(); ++m) {
        const WovenMaterial material(materials[m]);
        Sweep sweep(1000 + m);
        for (int q = 0; q < queriesPerMaterial && failures < 10; ++q) {
            const ShadingInput in = sweep.hit(materials[m]);
            const auto shading = material.shade(in);
            if (!shading) continue;
            ++shaded;
            const SurfaceBsdf& bsdf = shading->bsdf;
            // Half the queries around the bumped normal, half around the geometric one, so
            // directions between the two are hit too.
            const auto [wo, wi] = sweep.directions(q % 2 ? bsdf.shadingNormal() : in.ns);
            const Frame& frame = bsdf.frame();
            const glm::vec3 f = bsdf.eval(wo, wi);
            const float pdf = bsdf.pdf(wo, wi);
            const auto s = bsdf.sample(wo, {sweep.u(), sweep.u()}, sweep.u());
            std::string problem;
            if (!finite(frame.x) || !finite(frame.y) || !finite(frame.z) || !orthonormal(frame))
                problem = "frame not finite or not orthonormal";
            else if (!finite(f) || glm::any(glm::lessThan(f, glm::vec3(0.0f))))
                problem = "eval not finite or negative";
            else if (!std::isfinite(pdf) || pdf < 0.0f)
                problem = "pdf not finite or negative";
            else if (s) {
                ++sampled;
                if (!finite(s->wi) || std::abs(glm::length(s->wi) - 1.0f) > 1e-3f) problem = "sampled wi";
                else if (!finite(s->f) || glm::any(glm::lessThan(s->f, glm::vec3(0.0f)))) problem = "sampled f";
                else if (!std::isfinite(s->pdf) || s->pdf <= 0.0f) problem = "sampled pdf";
                else if (!finite(s->weight) || glm::any(glm::lessThan(s->weight, glm::vec3(0.0f))))
                    problem = "sample weight";
            }
            if (!problem.empty()) {
                ++failures;
                ADD_FAILURE() << "material " << m << ": " << problem << " at " << describe(in, wo, wi);
            }
        }
    }
    EXPECT_EQ(failures, 0);
    // The sweep must really have exercised the BSDF, not only gaps or failed samples.
    EXPECT_GT(shaded, 1'000'000);
    EXPECT_GT(sampled, 500'000);
}

}  // namespace
}  // namespace woven
