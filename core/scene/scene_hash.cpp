#include "scene_hash.h"

#include <xxhash.h>

#include <cstdio>
#include <type_traits>

#include "woven_params_json.h"

namespace woven {

namespace {

// XXH64 (libxxhash; OpenImageIO's copy of it before, so frames keep their scene's hash) chained
// over the values as they come: each call's digest seeds the next, so the order
// and the boundaries of the values are part of the hash.
class Hasher {
public:
    void bytes(const void* data, size_t size) { state_ = XXH64(data, size, state_); }

    // Numbers, enums and glm vectors and matrices: values without padding, hashed as stored.
    template <typename T>
    void add(const T& value) {
        static_assert(std::is_trivially_copyable_v<T> && !std::is_pointer_v<T>);
        bytes(&value, sizeof value);
    }
    template <typename T>
    void add(const std::vector<T>& values) {
        static_assert(std::is_trivially_copyable_v<T>);
        add(values.size());
        bytes(values.data(), values.size() * sizeof(T));
    }
    void add(const std::string& text) {
        add(text.size());
        bytes(text.data(), text.size());
    }

    uint64_t digest() const { return state_; }

private:
    unsigned long long state_ = 0x5ce9e;
};

// Field by field: the structs' padding bytes hold whatever was there.
void add(Hasher& h, const TextureRef& t) {
    h.add(t.image);
    h.add(t.texCoord);
    h.add(t.uvTransform);
    h.add(t.wrapS);
    h.add(t.wrapT);
    h.add(t.nearest);
    h.add(t.mipmaps);
    h.add(t.srgb);
    h.add(t.scale);
}

void add(Hasher& h, const Material& m) {
    h.add(m.woven.has_value());
    if (m.woven) h.add(paramsToJson(*m.woven).dump());
    h.add(m.keptSurface.has_value());
    if (m.keptSurface) {
        h.add(m.keptSurface->print);
        h.add(m.keptSurface->colorsFromFactor);
    }
    h.add(m.baseColor);
    add(h, m.baseColorTexture);
    h.add(m.metallic);
    h.add(m.roughness);
    add(h, m.metallicRoughnessTexture);
    add(h, m.normalTexture);
    add(h, m.occlusionTexture);
    h.add(m.emission);
    add(h, m.emissiveTexture);
    h.add(m.alphaMode);
    h.add(m.alphaCutoff);
    h.add(m.doubleSided);
    h.add(m.unlit);
    h.add(m.ior);
    h.add(m.specular);
    add(h, m.specularTexture);
    h.add(m.specularColor);
    add(h, m.specularColorTexture);
    h.add(m.sheen.color);
    add(h, m.sheen.colorTexture);
    h.add(m.sheen.roughness);
    add(h, m.sheen.roughnessTexture);
    h.add(m.anisotropy.strength);
    h.add(m.anisotropy.rotation);
    add(h, m.anisotropy.texture);
    h.add(m.clearcoat.factor);
    add(h, m.clearcoat.texture);
    h.add(m.clearcoat.roughness);
    add(h, m.clearcoat.roughnessTexture);
    add(h, m.clearcoat.normalTexture);
    h.add(m.transmission.factor);
    add(h, m.transmission.texture);
    h.add(m.transmission.thickness);
    add(h, m.transmission.thicknessTexture);
    h.add(m.transmission.attenuationColor);
    h.add(m.transmission.attenuationDistance);
    // Only where it shows, so that the frames of scenes without it keep the hashes they had.
    if (const IridescenceParams& i = m.iridescence; i.factor > 0.0f) {
        h.add(i.factor);
        add(h, i.texture);
        h.add(i.ior);
        h.add(i.thicknessMin);
        h.add(i.thicknessMax);
        add(h, i.thicknessTexture);
    }
    if (const DiffuseTransmissionParams& d = m.diffuseTransmission; d.factor > 0.0f) {
        h.add(d.factor);
        add(h, d.texture);
        h.add(d.color);
        add(h, d.colorTexture);
    }
}

void add(Hasher& h, const Mesh& m) {
    h.add(m.positions);
    h.add(m.normals);
    h.add(m.uvs);
    h.add(m.uvs1);
    h.add(m.colors);
    h.add(m.tangents);
    h.add(m.triangles);
    h.add(m.material);
    // Only where there are instances, so that every other scene keeps its hash.
    if (m.instances) h.add(*m.instances);
}

void add(Hasher& h, const TextureImage& t) {
    h.add(t.width);
    h.add(t.height);
    h.add(t.bytes);
    h.add(t.floats);
}

void add(Hasher& h, const PunctualLight& l) {
    h.add(l.type);
    h.add(l.position);
    h.add(l.direction);
    h.add(l.intensity);
    h.add(l.innerConeAngle);
    h.add(l.outerConeAngle);
}

template <typename T>
void addAll(Hasher& h, const std::vector<T>& items) {
    h.add(items.size());
    for (const T& item : items) add(h, item);
}

}  // namespace

std::string sceneHash(const SceneDescription& scene, const Camera& camera) {
    Hasher h;
    addAll(h, scene.meshes);
    addAll(h, scene.materials);
    addAll(h, scene.textures);
    addAll(h, scene.lights);
    h.add(scene.environment.color);
    h.add(scene.environment.rotation);
    h.add(scene.environment.image != nullptr);
    if (const Image* image = scene.environment.image.get()) {
        h.add(image->width);
        h.add(image->height);
        h.add(image->pixels);
    }
    h.add(camera.cameraToWorld);
    h.add(camera.yfov);
    h.add(camera.aspect);
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h.digest()));
    return hex;
}

}  // namespace woven
