// No NaN or Inf from GltfBxdf (the hard cases of tests/model's sweep, for the glTF lobes): a
// million queries, random and hard, each through eval, pdf and sample. Materials at the ends of
// their ranges and beyond (roughness 0 and 1, alpha clamped to 1e-3, sheen roughness 0, colours
// 0 and 1, scalars negative, huge, denormal and NaN, which the constructor must sanitise; colours
// stay finite, as the loader and 8-bit textures guarantee), clearcoat normals tilted to and past
// the horizon; directions grazing (1e-7 from the horizon), exactly on it (z = +0 and -0), along
// the normal, wo = wi, wo = -wi, wi = the mirror of wo (straight through), nearly opposite; the
// random numbers 0 and 1 - 2^-24.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "bsdf_test_util.h"
#include "gltf_bxdf.h"

namespace woven {
namespace {

using namespace woven::test;

class Sweep {
public:
    explicit Sweep(uint64_t seed) : rng_(seed) {}

    int pick(int n) { return std::min(n - 1, int(rng_.uniform(0.0, double(n)))); }

    // A scalar input: in range most of the time, else an end or something outside.
    float scalar() {
        switch (pick(12)) {
            case 0: return 0.0f;
            case 1: return 1.0f;
            case 2: return -1.0f;
            case 3: return 1e30f;
            case 4: return 1e-40f;  // denormal
            case 5: return std::numeric_limits<float>::quiet_NaN();
            case 6: return std::numeric_limits<float>::infinity();
            default: return float(rng_.uniform(0.0, 1.0));
        }
    }
    glm::vec3 color() {
        switch (pick(6)) {
            case 0: return glm::vec3(0.0f);
            case 1: return glm::vec3(1.0f);
            case 2: return glm::vec3(1e-40f, 1.0f, 0.0f);
            case 3: return glm::vec3(2.0f, 1e3f, 0.5f);  // out of range, finite
            default: return glm::vec3(rng_.color());
        }
    }
    glm::vec3 unit() { return toFloatUnit(rng_.sphere()); }

    GltfBxdfInputs inputs() {
        GltfBxdfInputs in;
        in.baseColor = color();
        in.metallic = scalar();
        in.roughness = scalar();
        in.specularF0 = color();
        in.specularF90 = scalar();
        in.transmission = pick(2) ? scalar() : 0.0f;
        in.transmittance = color();
        if (pick(2)) {
            in.diffuseTransmission = scalar();
            in.diffuseTransmissionColor = color();
        }
        if (pick(2)) {
            in.sheenColor = color();
            in.sheenRoughness = scalar();
        }
        if (pick(2)) {
            in.clearcoat = scalar();
            in.clearcoatRoughness = scalar();
            switch (pick(5)) {
                case 0: in.clearcoatNormal = glm::vec3(0.0f, 0.0f, 1.0f); break;
                case 1: in.clearcoatNormal = glm::normalize(glm::vec3(1.0f, 0.5f, 0.0f)); break;  // on the horizon
                case 2: in.clearcoatNormal = glm::normalize(glm::vec3(0.3f, -0.2f, -0.5f)); break;  // below it
                default: {
                    glm::vec3 n = unit();
                    n.z = std::abs(n.z);
                    in.clearcoatNormal = n;
                }
            }
        }
        return in;
    }

    // Directions in the local frame, random and hard.
    std::pair<glm::vec3, glm::vec3> directions() {
        glm::vec3 wo = unit(), wi = unit();
        wo.z = std::abs(wo.z);
        const auto grazing = [&](float side) {
            glm::vec3 r = unit();
            r.z = 0.0f;
            return glm::normalize(glm::normalize(r) + glm::vec3(0.0f, 0.0f, side * 1e-7f));
        };
        switch (pick(12)) {
            case 0: break;
            case 1: wo = grazing(1.0f); break;
            case 2: wo = grazing(1.0f); wi = grazing(pick(2) ? 1.0f : -1.0f); break;
            case 3: wi = wo; break;
            case 4: wi = -wo; break;
            case 5: wi = mirror(wo); break;  // straight through the thin wall
            case 6: wi = glm::normalize(-wo + 1e-6f * unit()); break;
            case 7: wo = glm::vec3(0.0f, 0.0f, 1.0f); wi = pick(2) ? wo : -wo; break;
            case 8: wi = glm::vec3(wi.x, wi.y, pick(2) ? 0.0f : -0.0f); break;  // exactly on the horizon
            case 9: wo = glm::vec3(wo.x, wo.y, 0.0f); break;
            case 10: wo.z = -wo.z; break;  // from below: no BSDF there
            default: wi = glm::vec3(-wo.x, -wo.y, wo.z); break;  // the mirror direction
        }
        return {wo, wi};
    }

    float u() { return pick(10) ? rng_.u() : (pick(2) ? 0.0f : 0x1.fffffep-1f); }

private:
    TestRng rng_;
};

bool nonNegative(const glm::vec3& v) { return finite(v) && v.x >= 0.0f && v.y >= 0.0f && v.z >= 0.0f; }

TEST(GltfNoNan, AMillionHardQueries) {
    Sweep sweep(31337);
    constexpr int kMaterials = 5000, kQueries = 200;
    int failures = 0;
    long sampled = 0, nonZero = 0;
    for (int i = 0; i < kMaterials && failures < 10; ++i) {
        const GltfBxdfInputs in = sweep.inputs();
        const GltfBxdf bxdf(in);
        for (int q = 0; q < kQueries && failures < 10; ++q) {
            const auto [wo, wi] = sweep.directions();
            const glm::vec3 f = bxdf.eval(wo, wi);
            const float pdf = bxdf.pdf(wo, wi);
            const auto s = bxdf.sample(wo, {sweep.u(), sweep.u()}, sweep.u());
            std::string problem;
            if (!nonNegative(f)) problem = "eval not finite or negative: " + describe(f);
            else if (!std::isfinite(pdf) || pdf < 0.0f) problem = "pdf not finite or negative: " + std::to_string(pdf);
            else if (!(wo.z > 0.0f) && (f != glm::vec3(0.0f) || pdf != 0.0f || s)) problem = "a BSDF seen from below";
            else if (s) {
                ++sampled;
                if (!finite(s->wi) || std::abs(glm::length(s->wi) - 1.0f) > 1e-4f) problem = "sampled wi " + describe(s->wi);
                else if (!nonNegative(s->f)) problem = "sampled f " + describe(s->f);
                else if (!std::isfinite(s->pdf) || !(s->pdf > 0.0f)) problem = "sampled pdf " + std::to_string(s->pdf);
                else if (!nonNegative(s->weight)) problem = "sample weight " + describe(s->weight);
                else if (s->wi.z < 0.0f && !bxdf.transmits()) problem = "transmitted by a BSDF that does not transmit";
            }
            nonZero += f != glm::vec3(0.0f);
            if (!problem.empty()) {
                ++failures;
                ADD_FAILURE() << problem << " at wo " << describe(wo) << " wi " << describe(wi) << " base "
                              << describe(in.baseColor) << " metallic " << in.metallic << " roughness " << in.roughness
                              << " F0 " << describe(in.specularF0) << " F90 " << in.specularF90 << " T "
                              << in.transmission << " DT " << in.diffuseTransmission << " "
                              << describe(in.diffuseTransmissionColor) << " sheen " << describe(in.sheenColor) << " r " << in.sheenRoughness
                              << " coat " << in.clearcoat << " r " << in.clearcoatRoughness << " n "
                              << describe(in.clearcoatNormal);
            }
        }
    }
    EXPECT_EQ(failures, 0);
    // The sweep must really have exercised the BSDF, not only zeros and failed samples.
    EXPECT_GT(nonZero, 300000);
    EXPECT_GT(sampled, 500000);
}

}  // namespace
}  // namespace woven
