#include "gltf_material.h"

#include <algorithm>
#include <cmath>

#include "normal_map.h"

namespace woven {

namespace {

bool usableLength(float length) { return length > 1e-12f && std::isfinite(length); }

// A normal map can tilt the shading normal so far that the mirror direction of the view falls
// below the surface, where no light can come from: the specular highlight turns black. As
// Cycles does, tilt such a normal back just enough that the mirror direction stays `margin`
// above the geometric surface (all unit vectors, ng and n on the viewer's side).
glm::vec3 keepReflectionAbove(const glm::vec3& ng, const glm::vec3& wo, const glm::vec3& n) {
    const float cosView = glm::dot(wo, ng);
    const float margin = std::min(0.9f * cosView, 0.01f);
    const glm::vec3 r = 2.0f * glm::dot(wo, n) * n - wo;
    if (glm::dot(r, ng) >= margin) return n;
    const glm::vec3 tangential = r - glm::dot(r, ng) * ng;
    const float length = glm::length(tangential);
    if (!usableLength(length) || !(cosView > 0.0f)) return n;
    const glm::vec3 bent = std::sqrt(1.0f - margin * margin) * (tangential / length) + margin * ng;
    const glm::vec3 half = wo + bent;
    const float halfLength = glm::length(half);
    return usableLength(halfLength) ? half / halfLength : n;
}

// The attenuation of one crossing of a thin wall: half of the volume's thickness.
glm::vec3 crossingTransmittance(const TransmissionParams& t, float thickness) {
    if (!(thickness > 0.0f) || !std::isfinite(t.attenuationDistance) || !(t.attenuationDistance > 0.0f))
        return glm::vec3(1.0f);
    const glm::vec3 c = glm::clamp(t.attenuationColor, glm::vec3(1e-6f), glm::vec3(1.0f));
    return glm::pow(c, glm::vec3(0.5f * thickness / t.attenuationDistance));
}

}  // namespace

GltfMaterial::GltfMaterial(const Material& material, const std::vector<TextureImage>& textures)
    : SurfaceMaterial(material, textures),
      m_(material),
      baseColor_(material, textures),
      metallicRoughnessTexture_(material.metallicRoughnessTexture, textures),
      normalTexture_(material.normalTexture, textures),
      specularTexture_(material.specularTexture, textures),
      specularColorTexture_(material.specularColorTexture, textures),
      sheenColorTexture_(material.sheen.colorTexture, textures),
      sheenRoughnessTexture_(material.sheen.roughnessTexture, textures),
      anisotropyTexture_(material.anisotropy.texture, textures),
      clearcoatTexture_(material.clearcoat.texture, textures),
      clearcoatRoughnessTexture_(material.clearcoat.roughnessTexture, textures),
      clearcoatNormalTexture_(material.clearcoat.normalTexture, textures),
      transmissionTexture_(material.transmission.texture, textures),
      thicknessTexture_(material.transmission.thicknessTexture, textures),
      diffuseTransmissionTexture_(material.diffuseTransmission.texture, textures),
      diffuseTransmissionColorTexture_(material.diffuseTransmission.colorTexture, textures),
      iridescenceTexture_(material.iridescence.texture, textures),
      iridescenceThicknessTexture_(material.iridescence.thicknessTexture, textures) {
    // KHR_materials_ior: an IOR of 0 stands for an infinite one (a perfect mirror's F0 of 1).
    const float ior = material.ior;
    dielectricF0_ = ior == 0.0f ? 1.0f : ((ior - 1.0f) / (ior + 1.0f)) * ((ior - 1.0f) / (ior + 1.0f));
    const TextureSampler* const lobeTextures[] = {
        &metallicRoughnessTexture_, &specularTexture_, &specularColorTexture_, &sheenColorTexture_,
        &sheenRoughnessTexture_, &anisotropyTexture_, &transmissionTexture_, &thicknessTexture_,
        &diffuseTransmissionTexture_, &diffuseTransmissionColorTexture_, &iridescenceTexture_,
        &iridescenceThicknessTexture_};
    const bool textured = baseColor_.textured() ||
                          std::any_of(std::begin(lobeTextures), std::end(lobeTextures), [](const TextureSampler* t) { return bool(*t); });
    // The coat's lobe holds its normal in the hit's frame, so a coated surface builds it per hit.
    if (!textured && !m_.unlit && !(m_.clearcoat.factor > 0.0f)) {
        const GltfBxdfInputs in = inputs(TexCoords{});
        uniform_.emplace(UniformLobes{GltfBxdf(in), in.anisotropy});
    }
}

GltfBxdfInputs GltfMaterial::inputs(const TexCoords& tc) const {
    GltfBxdfInputs in;
    in.baseColor = glm::vec3(baseColor_.eval(tc));
    const glm::vec4 mr = metallicRoughnessTexture_.eval(tc);
    in.metallic = m_.metallic * mr.b;
    in.roughness = m_.roughness * mr.g;
    if (m_.anisotropy.strength > 0.0f) in.anisotropy = m_.anisotropy.strength * anisotropyTexture_.eval(tc).b;
    const float specular = m_.specular * specularTexture_.eval(tc).a;
    const glm::vec3 specularColor = m_.specularColor * glm::vec3(specularColorTexture_.eval(tc));
    in.specularF0 = glm::min(dielectricF0_ * specularColor, glm::vec3(1.0f)) * specular;
    in.specularF90 = specular;
    const TransmissionParams& t = m_.transmission;
    if (t.factor > 0.0f) {
        in.transmission = t.factor * transmissionTexture_.eval(tc).r;
        in.transmittance = crossingTransmittance(t, t.thickness * thicknessTexture_.eval(tc).g);
    }
    if (const DiffuseTransmissionParams& d = m_.diffuseTransmission; d.factor > 0.0f) {
        in.diffuseTransmission = d.factor * diffuseTransmissionTexture_.eval(tc).a;
        in.diffuseTransmissionColor = d.color * glm::vec3(diffuseTransmissionColorTexture_.eval(tc));
    }
    if (m_.sheen.color != glm::vec3(0.0f)) {
        in.sheenColor = m_.sheen.color * glm::vec3(sheenColorTexture_.eval(tc));
        in.sheenRoughness = m_.sheen.roughness * sheenRoughnessTexture_.eval(tc).a;
    }
    if (m_.clearcoat.factor > 0.0f) {
        in.clearcoat = m_.clearcoat.factor * clearcoatTexture_.eval(tc).r;
        in.clearcoatRoughness = m_.clearcoat.roughness * clearcoatRoughnessTexture_.eval(tc).g;
    }
    if (const IridescenceParams& i = m_.iridescence; i.factor > 0.0f) {
        in.iridescence = i.factor * iridescenceTexture_.eval(tc).r;
        in.iridescenceIor = i.ior;
        in.iridescenceThickness = iridescenceThicknessTexture_
                                      ? glm::mix(i.thicknessMin, i.thicknessMax, iridescenceThicknessTexture_.eval(tc).g)
                                      : i.thicknessMax;
    }
    return in;
}

glm::vec3 GltfMaterial::shadingNormal(const SurfaceHit& hit) const {
    return normalTexture_ ? normalMapped(normalTexture_, hit) : hit.ns;
}

glm::vec3 GltfMaterial::anisotropyDirection(const SurfaceHit& hit) const {
    const std::optional<Frame> tbn = tangentSpace(hit);
    if (!tbn) return Frame::fromNormal(hit.ns).x;
    // The texture's direction (the tangent where it has none, or where it is zero), turned by
    // the rotation: the extension's reference implementation.
    glm::vec2 d(1.0f, 0.0f);
    if (anisotropyTexture_) {
        const glm::vec2 t = glm::vec2(anisotropyTexture_.eval(hit.tex)) * 2.0f - 1.0f;
        const float length = glm::length(t);
        if (usableLength(length)) d = t / length;
    }
    const float c = std::cos(m_.anisotropy.rotation), s = std::sin(m_.anisotropy.rotation);
    return tbn->toWorld(glm::vec3(c * d.x - s * d.y, s * d.x + c * d.y, 0.0f));
}

Frame GltfMaterial::lobeFrame(const SurfaceHit& hit, const glm::vec3& n, float anisotropy) const {
    return anisotropy > 0.0f ? Frame::fromNormalAndAxis(n, anisotropyDirection(hit)) : Frame::fromNormal(n);
}

std::optional<Bsdf> GltfMaterial::bsdf(const SurfaceHit& hit, const glm::vec3& wo) const {
    if (m_.unlit) return std::nullopt;
    const float side = glm::dot(wo, hit.ng) < 0.0f ? -1.0f : 1.0f;
    const glm::vec3 ng = side * hit.ng;
    glm::vec3 n = side * shadingNormal(hit);
    if (normalTexture_) n = keepReflectionAbove(ng, wo, n);
    if (uniform_ && hit.tex.color == glm::vec4(1.0f))
        return std::optional<Bsdf>(std::in_place, lobeFrame(hit, n, uniform_->anisotropy), std::in_place,
                                   std::in_place_type<GltfBxdf>, uniform_->bxdf);
    GltfBxdfInputs in = inputs(hit.tex);
    const Frame frame = lobeFrame(hit, n, in.anisotropy);
    if (in.clearcoat > 0.0f) {
        // The coat follows the geometry's normal unless it has a normal map of its own.
        glm::vec3 coat = side * hit.ns;
        if (clearcoatNormalTexture_) coat = keepReflectionAbove(ng, wo, side * normalMapped(clearcoatNormalTexture_, hit));
        in.clearcoatNormal = frame.toLocal(coat);
    }
    // Built where it is returned: a copy of the BSDF costs about what its lobe's constructor does.
    return std::optional<Bsdf>(std::in_place, frame, std::in_place, std::in_place_type<GltfBxdf>, in);
}

bool GltfMaterial::mayPassThrough(const Mesh& mesh) const { return baseColor_.mayPassThrough(mesh); }

bool GltfMaterial::passesThrough(const TexCoords& tc, float u) const { return baseColor_.passesThrough(tc, u); }

glm::vec3 GltfMaterial::unlitRadiance(const TexCoords& tc) const {
    return m_.unlit ? glm::max(glm::vec3(baseColor_.eval(tc)), glm::vec3(0.0f)) : glm::vec3(0.0f);
}

}  // namespace woven
