#include "woven_material.h"

#include <algorithm>
#include <cmath>

#include "yarn_noise.h"

namespace woven {

namespace {
glm::vec3 projectOut(const glm::vec3& v, const glm::vec3& n) { return v - glm::dot(v, n) * n; }
// A projection is usable when it keeps a fair part of the vector it came from: what is left of a
// vector (nearly) parallel to n is rounding noise that points anywhere, even along n.
bool usable(const glm::vec3& projected, const glm::vec3& original) {
    const float l2 = glm::dot(projected, projected);
    return l2 > 1e-10f * glm::dot(original, original) && l2 > 1e-30f && std::isfinite(l2);
}
}  // namespace

Frame tangentFrame(const glm::vec3& n, const glm::vec3& dpdu, const glm::vec3& dpdv) {
    glm::vec3 t = projectOut(dpdu, n);
    glm::vec3 b = projectOut(dpdv, n);
    Frame f;
    f.z = n;
    if (usable(t, dpdu)) {
        f.x = glm::normalize(t);
        // y is n x x up to the sign of dp/dv (it tells which way +v runs, on either face).
        // Taking the sign only keeps the frame orthonormal when dp/du and dp/dv are nearly
        // parallel, where Gram-Schmidt of dp/dv against x leaves mostly rounding noise.
        f.y = glm::cross(n, f.x);
        if (usable(b, dpdv) && glm::dot(b, f.y) < 0.0f) f.y = -f.y;
    } else if (usable(b, dpdv)) {
        f.y = glm::normalize(b);
        f.x = glm::cross(f.y, n);
    } else {
        return Frame::fromNormal(n);
    }
    return f;
}

WovenMaterial::WovenMaterial(const WovenParams& params)
    : params_((validate(params), params)),
      weave_(params),
      farField_{WeaveFarField(weave_, params_, false), WeaveFarField(weave_, params_, true)},
      mayHaveGaps_(mayBeSeenThrough(params)),
      transmits_(false) {
    for (int i = 0; i < weave_.yarnCount(); ++i) transmits_ = transmits_ || weave_.yarn(i).transmission() > 0.0f;
}

bool WovenMaterial::isSeeThrough(const glm::dvec2& uv) const {
    if (!mayHaveGaps_) return false;
    // Both yarns' coverage is the same on either face, so the front tile answers for both.
    return yarnAt(weave_, params_, false, uv).type == YarnType::Gap;
}

namespace {
// The footprint the filter averages over, as a fraction of the pixel's: the renderer already
// averages over the pixel by its jittered samples, so a whole pixel here would blur the image by
// a second pixel (measured: half a pixel halves the filter's bias on the paper's satin).
constexpr double kFootprintScale = 0.5;
Frame faceTangentFrame(const ShadingInput& in) {
    return tangentFrame(in.backSide ? -in.ns : in.ns, in.dpdu, in.dpdv);
}
}  // namespace

std::optional<WovenShading> WovenMaterial::shade(const ShadingInput& in) const {
    return shade(in, faceTangentFrame(in));
}

std::optional<FramedLobe<FilteredWeaveLobe>> WovenMaterial::shadeFiltered(const ShadingInput& in) const {
    // The footprint in weave elements: |de/dx| + |de/dy| along u and along v, as GLSL's fwidth.
    const glm::dvec2 repeat(params_.repeat);
    const glm::dvec2 dedx = kFootprintScale * in.duvdx * repeat, dedy = kFootprintScale * in.duvdy * repeat;
    const glm::dvec2 pixel = glm::abs(dedx) + glm::abs(dedy), spacing = in.uvSpacing * repeat;
    const glm::dvec2 extent = glm::max(pixel, spacing);
    const float farWeight = farFieldWeight(float(std::max(extent.x, extent.y)));
    if (!(farWeight > 0.0f)) return std::nullopt;
    const Frame tangent = faceTangentFrame(in);
    Frame nearFrame;
    std::optional<AshikhminShirley> nearLobe;
    if (farWeight < 1.0f) {
        const auto near = shade(in, tangent);
        if (!near) return std::nullopt;  // a see-through gap: rays pass it by its exact uv
        const Frame& f = near->bsdf.frame();
        nearFrame = Frame{tangent.toLocal(f.x), tangent.toLocal(f.y), tangent.toLocal(f.z)};
        nearLobe = near->bsdf.lobe();
    }
    // Each side's mean colour over the footprint's extent along its threads' axis.
    // A footprint of 2^40 elements averages any thread layout (periods of up to 2^16) to within
    // 2^-24; capped there, a huge uv's spacing keeps the means' thread indices within 64 bits.
    // Where the uv's spacing is the larger the point is anywhere in it: whole repeats' shares and
    // colours, not those of a box around where it rounded to (woven.frag does the same).
    constexpr double kWholeRepeats = 0x1p40;
    const bool unresolved = std::max(spacing.x, spacing.y) > std::max(pixel.x, pixel.y);
    const glm::dvec2 e = weave_.wrapped(in.uv * repeat),
                     half = unresolved ? glm::dvec2(kWholeRepeats) : glm::min(0.5 * extent, glm::dvec2(kWholeRepeats));
    const WeaveFarField& far = farField(in.backSide);
    glm::vec3 warp = weave_.warp().meanColor(e.x - half.x, e.x + half.x), weft = weave_.weft().meanColor(e.y - half.y, e.y + half.y);
    if (!unresolved) far.footprintColors(e - half, e + half, warp, weft);
    const glm::vec3 colors[3] = {warp * in.print, weft * in.print, params_.backing_color};
    const FilteredWeaveLobe lobe(far, colors, far.footprintScales(e - half, e + half), farWeight, nearFrame,
                                 nearLobe.value_or(AshikhminShirley(0.0f, 0.0f, 0.0f, glm::vec3(0.0f))));
    return FramedLobe<FilteredWeaveLobe>(tangent, lobe);
}

namespace {
// A yarn point as shading sees it: its yarn and lobe shape, its colour (noise and print applied)
// and its frame.
struct YarnLook {
    const Yarn* yarn;
    const LobeShape* shape;
    glm::vec3 color;
    Frame frame;
};
YarnLook look(const Weave& weave, const WovenParams& params, const YarnPoint& y, const Frame& tangent, const glm::vec3& print) {
    const bool weft = y.type == YarnType::Weft;
    const Yarn& yarn = weave.yarn(y.yarn);
    glm::vec3 color = (weft ? weave.weft() : weave.warp()).color(y.slot);
    if (yarn.noise() > 0.0f) {
        // The seed wraps the yarn index to 32 bits, as the GLSL twin does.
        const uint32_t seed = uint32_t(y.yarnIndex) * 2U + (weft ? 0U : 1U);
        const float n01 = yarnNoise(y.along * params.noise_scale, seed);
        color = glm::clamp(color * (1.0f + yarn.noise() * n01), 0.0f, 1.0f);
    }
    color *= print;
    const glm::vec3 bumped = tangent.toWorld(y.normal);
    return {&yarn, &weave.lobeShape(y.yarn), color, Frame::fromNormalAndAxis(bumped, weft ? tangent.x : tangent.y)};
}
}  // namespace

std::optional<WovenShading> WovenMaterial::shade(const ShadingInput& in, const Frame& tangent) const {
    const YarnPoint y = yarnAt(weave_, params_, in.backSide, in.uv);

    if (y.type == YarnType::Gap) {
        if (!params_.backing) return std::nullopt;
        return WovenShading{YarnType::Gap, SurfaceBsdf(tangent, AshikhminShirley(0.0f, 0.0f, 0.0f, params_.backing_color))};
    }
    const YarnLook seen = look(weave_, params_, y, tangent, in.print);
    const AshikhminShirley lobe(*seen.shape, seen.color);
    if (!(seen.yarn->transmission() > 0.0f)) return WovenShading{y.type, SurfaceBsdf(seen.frame, lobe)};
    // Light crosses both faces' yarns at the point: it passes what the one that passes less
    // does, through the front face's yarn lobe, whichever face is seen (MODEL_TRANSMISSION.md 3).
    const YarnPoint o = yarnAt(weave_, params_, !in.backSide, in.uv);
    if (o.type == YarnType::Gap || !(weave_.yarn(o.yarn).transmission() > 0.0f))
        return WovenShading{y.type, SurfaceBsdf(seen.frame, lobe)};
    const Frame otherTangent = tangentFrame(in.backSide ? in.ns : -in.ns, in.dpdu, in.dpdv);
    const YarnLook other = look(weave_, params_, o, otherTangent, in.print);
    const glm::vec3 passed = glm::min(yarnTransmittance(seen.color, seen.yarn->transmission()),
                                      yarnTransmittance(other.color, other.yarn->transmission()));
    const YarnLook& front = in.backSide ? other : seen;
    const YarnTransmission through(*front.shape, passed, front.yarn->transmissionGloss());
    return WovenShading{y.type, SurfaceBsdf(seen.frame, lobe), FramedLobe<YarnTransmission>(front.frame, through)};
}

}  // namespace woven
