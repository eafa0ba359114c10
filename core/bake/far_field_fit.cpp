#include "far_field_fit.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "far_field.h"
#include "gltf_material.h"
#include "sheen_lobe.h"
#include "woven_surface_material.h"

namespace woven {

namespace {

constexpr int kFitPoints = 512;      // the baked material's points: its textures are smooth
constexpr int kTargetPoints = 4096;  // the model's: yarn edges and gaps are sharp

// The baked material at one point and direction pair, split into the parts its far field is
// linear in. With base colour scale k and specular factor s (F = s F1, F1 the Fresnel term at
// s = 1), glTF's dielectric is (1 - s F1) k base / pi + s F1 D V = k diffuse - k s coupling + s specular.
struct PointPair {
    glm::vec3 diffuse{0.0f}, coupling{0.0f}, specular{0.0f};  // reflectances (times |wi.n|)
    glm::vec3 wo{0.0f}, wi{0.0f};  // local, z = the shading normal: for the sheen layer
    bool covered = false;
};

// Sums over the points, per direction pair, of each part unscaled and times E = the sheen
// layer's max(E(wo), E(wi)) (the base under a sheen of largest channel m is scaled by 1 - m E),
// and of the sheen lobe (colour 1): the far field for any k, s and sheen of this roughness is a
// combination of them.
struct Parts {
    std::vector<glm::dvec3> diffuse, diffuseE, coupling, couplingE, specular, specularE;
    std::vector<double> sheen;
};

Parts sumParts(const std::vector<PointPair>& samples, size_t pairs, float roughness) {
    const SheenLobe lobe(glm::vec3(1.0f), roughness);
    Parts p;
    for (auto* v : {&p.diffuse, &p.diffuseE, &p.coupling, &p.couplingE, &p.specular, &p.specularE}) v->assign(pairs, glm::dvec3(0.0));
    p.sheen.assign(pairs, 0.0);
    const double points = double(samples.size() / pairs);
    for (size_t i = 0; i < samples.size(); ++i) {
        const PointPair& s = samples[i];
        if (!s.covered) continue;
        const size_t j = i % pairs;
        const double e = std::max(lobe.albedo(s.wo.z), lobe.albedo(s.wi.z));
        p.diffuse[j] += glm::dvec3(s.diffuse) / points;
        p.diffuseE[j] += glm::dvec3(s.diffuse) * e / points;
        p.coupling[j] += glm::dvec3(s.coupling) / points;
        p.couplingE[j] += glm::dvec3(s.coupling) * e / points;
        p.specular[j] += glm::dvec3(s.specular) / points;
        p.specularE[j] += glm::dvec3(s.specular) * e / points;
        p.sheen[j] += double(lobe.eval(s.wo, s.wi).g) * std::max(s.wi.z, 0.0f) / points;
    }
    return p;
}

struct Candidate {
    double k = 1.0, s = 1.0, error = std::numeric_limits<double>::infinity();
    glm::dvec3 c{0.0};
};

// k, s and the sheen colour (largest channel at most m) for one sheen roughness, by alternating
// least squares (each step exact for its unknown, so the error never grows); the error is then
// that of the base scaled by the colour's own largest channel.
Candidate solve(const Parts& p, const std::vector<glm::vec3>& target, double m) {
    const size_t n = target.size();
    std::vector<glm::dvec3> d(n), c(n), s(n);
    const auto scaled = [&](double mm) {
        for (size_t j = 0; j < n; ++j) {
            d[j] = p.diffuse[j] - mm * p.diffuseE[j];
            c[j] = p.coupling[j] - mm * p.couplingE[j];
            s[j] = p.specular[j] - mm * p.specularE[j];
        }
    };
    const auto model = [&](const Candidate& x, size_t j) { return x.k * d[j] - x.k * x.s * c[j] + x.s * s[j] + x.c * p.sheen[j]; };
    scaled(m);
    Candidate x;
    for (int round = 0; round < 8; ++round) {
        double num = 0.0, den = 0.0;
        for (size_t j = 0; j < n; ++j) {
            const glm::dvec3 basis = d[j] - x.s * c[j], rest = glm::dvec3(target[j]) - x.s * s[j] - x.c * p.sheen[j];
            num += glm::dot(basis, rest), den += glm::dot(basis, basis);
        }
        if (den > 0.0) x.k = std::max(0.0, num / den);
        num = den = 0.0;
        for (size_t j = 0; j < n; ++j) {
            const glm::dvec3 basis = s[j] - x.k * c[j], rest = glm::dvec3(target[j]) - x.k * d[j] - x.c * p.sheen[j];
            num += glm::dot(basis, rest), den += glm::dot(basis, basis);
        }
        if (den > 0.0) x.s = std::clamp(num / den, 0.0, 1.0);
        if (m > 0.0) {
            glm::dvec3 cn(0.0);
            double cd = 0.0;
            for (size_t j = 0; j < n; ++j) {
                cn += (glm::dvec3(target[j]) - x.k * d[j] + x.k * x.s * c[j] - x.s * s[j]) * p.sheen[j];
                cd += p.sheen[j] * p.sheen[j];
            }
            if (cd > 0.0) x.c = glm::clamp(cn / cd, 0.0, m);
        }
    }
    scaled(std::max({x.c.r, x.c.g, x.c.b}));
    x.error = 0.0;
    for (size_t j = 0; j < n; ++j) {
        const glm::dvec3 e = glm::dvec3(target[j]) - model(x, j);
        x.error += glm::dot(e, e);
    }
    return x;
}

}  // namespace

FarFieldFit fitFarField(const WovenParams& params, const Material& baked, const std::vector<TextureImage>& textures,
                        glm::dvec2 uvSize, bool sheen) {
    Material wovenMaterial;
    wovenMaterial.woven = params;
    const WovenSurfaceMaterial woven(wovenMaterial, {});
    const std::vector<DirectionPair>& directions = farFieldDirections();
    const std::vector<glm::vec3> target = farField(woven, farFieldPoints(uvSize, kTargetPoints), directions);

    // The baked material with specular 0 (pure diffuse) and with a black base (pure specular).
    Material diffuseOnly = baked, specularOnly = baked;
    diffuseOnly.specular = 0.0f;
    specularOnly.baseColor = glm::vec4(0.0f, 0.0f, 0.0f, baked.baseColor.a);
    const GltfMaterial both(baked, textures), diffuse(diffuseOnly, textures), specular(specularOnly, textures);
    const std::vector<glm::dvec2> points = farFieldPoints(uvSize, kFitPoints);
    std::vector<PointPair> samples(points.size() * directions.size());
    tbb::parallel_for(size_t(0), points.size(), [&](size_t p) {
        const SurfaceHit hit = flatHit(points[p]);
        if (both.passesThrough(hit.tex, 0.0f)) return;
        std::optional<Bsdf> b, bd, bs;
        for (size_t j = 0; j < directions.size(); ++j) {
            const DirectionPair& pair = directions[j];
            if (j == 0 || pair.wo != directions[j - 1].wo) b = both.bsdf(hit, pair.wo), bd = diffuse.bsdf(hit, pair.wo), bs = specular.bsdf(hit, pair.wo);
            if (!b) continue;
            const float cosine = std::abs(glm::dot(pair.wi, b->shadingNormal()));
            PointPair& s = samples[p * directions.size() + j];
            s.covered = true;
            s.diffuse = bd->eval(pair.wo, pair.wi) * cosine;
            s.specular = bs->eval(pair.wo, pair.wi) * cosine;
            s.coupling = s.diffuse + s.specular - b->eval(pair.wo, pair.wi) * cosine;
            s.wo = b->frame().toLocal(pair.wo);
            s.wi = b->frame().toLocal(pair.wi);
        }
    });

    // Per sheen roughness, the largest channel m on a fine grid (each is cheap once the parts are summed).
    const int roughnesses = sheen ? 10 : 1;
    std::vector<Candidate> best(static_cast<size_t>(roughnesses));
    tbb::parallel_for(0, roughnesses, [&](int r) {
        const Parts parts = sumParts(samples, directions.size(), 0.1f * float(r + 1));
        for (int step = 0; step <= (sheen ? 100 : 0); ++step) {
            const Candidate c = solve(parts, target, step / 100.0);
            if (c.error < best[size_t(r)].error) best[size_t(r)] = c;
        }
    });
    const auto winner = std::min_element(best.begin(), best.end(), [](const Candidate& a, const Candidate& b) { return a.error < b.error; });

    double norm = 0.0;
    for (const glm::vec3& t : target) norm += glm::dot(glm::dvec3(t), glm::dvec3(t));
    const Parts unit = sumParts(samples, directions.size(), 0.1f);
    double before = 0.0;
    for (size_t j = 0; j < target.size(); ++j) {
        const glm::dvec3 e = glm::dvec3(target[j]) - (unit.diffuse[j] - unit.coupling[j] + unit.specular[j]);
        before += glm::dot(e, e);
    }
    FarFieldFit fit;
    fit.baseScale = float(winner->k);
    fit.specular = float(winner->s);
    if (std::max({winner->c.r, winner->c.g, winner->c.b}) > 0.0) {
        fit.sheen.color = glm::vec3(winner->c);
        fit.sheen.roughness = 0.1f * float(winner - best.begin() + 1);
    }
    fit.before = norm > 0.0 ? std::sqrt(before / norm) : 0.0;
    fit.after = norm > 0.0 ? std::sqrt(winner->error / norm) : 0.0;
    return fit;
}

}  // namespace woven
