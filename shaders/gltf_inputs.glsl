// The glTF material's inputs at a fragment, as core's GltfMaterial looks them up: each factor
// (gltfUniformTable(), app/preview/gltf_gl_material.cpp) times its texture, clamped as core
// clamps them. For gltf.frag's shading and gltf_shadow.frag's coloured shadows.

// The base colour and alpha: factor x vertex colour x texture.
vec4 gltfBaseColor() {
    vec4 base = baseColorFactor * vColor;
#ifdef MAP_BASE_COLOR
    base *= lookup(MAP_BASE_COLOR);
#endif
    return base;
}

// `baseColor`: gltfBaseColor()'s colour, unclamped; `anisotropy` and `direction` (in the
// (tangent, bitangent) plane) give the lobe's frame.
GltfInputs gltfInputs(vec3 baseColor, out float anisotropy, out vec2 direction) {
    GltfInputs g;
    g.baseColor = clamp(baseColor, 0.0, 1.0);
    float metallic = metallicFactor, roughness = roughnessFactor;
#ifdef MAP_METALLIC_ROUGHNESS
    vec4 mr = lookup(MAP_METALLIC_ROUGHNESS);
    metallic *= mr.b;
    roughness *= mr.g;
#endif
    g.metallic = clamp(metallic, 0.0, 1.0);
    roughness = clamp(roughness, 0.0, 1.0);
    g.alpha = clamp(roughness * roughness, 1e-3, 1.0);
    anisotropy = anisotropyStrength;
    direction = vec2(1.0, 0.0);  // in (tangent, bitangent) space, as core's anisotropyDirection()
#ifdef MAP_ANISOTROPY
    vec3 anisotropyTexel = lookup(MAP_ANISOTROPY).rgb;
    anisotropy *= anisotropyTexel.b;
    vec2 textureDirection = anisotropyTexel.rg * 2.0 - 1.0;
    if (dot(textureDirection, textureDirection) > 1e-24) direction = normalize(textureDirection);
#endif
    direction = mat2(anisotropyRotation.x, anisotropyRotation.y, -anisotropyRotation.y, anisotropyRotation.x) * direction;
    anisotropy = clamp(anisotropy, 0.0, 1.0);
    g.alphaX = clamp(mix(roughness * roughness, 1.0, anisotropy * anisotropy), 1e-3, 1.0);
    float specular = specularFactor;
    vec3 specularColor = specularColorFactor;
#ifdef MAP_SPECULAR
    specular *= lookup(MAP_SPECULAR).a;
#endif
#ifdef MAP_SPECULAR_COLOR
    specularColor *= lookup(MAP_SPECULAR_COLOR).rgb;
#endif
    g.f0 = min(iorF0 * specularColor, vec3(1.0)) * specular;
    g.f90 = specular;
    g.transmission = transmissionFactor;
#ifdef MAP_TRANSMISSION
    g.transmission *= lookup(MAP_TRANSMISSION).r;
#endif
    g.diffuseTransmission = 0.0;
    g.diffuseTransmissionColor = vec3(0.0);
#ifdef DIFFUSE_TRANSMISSION
    g.diffuseTransmission = diffuseTransmissionFactor;
    g.diffuseTransmissionColor = diffuseTransmissionColorFactor;
#ifdef MAP_DIFFUSE_TRANSMISSION
    g.diffuseTransmission *= lookup(MAP_DIFFUSE_TRANSMISSION).a;
#endif
#ifdef MAP_DIFFUSE_TRANSMISSION_COLOR
    g.diffuseTransmissionColor *= lookup(MAP_DIFFUSE_TRANSMISSION_COLOR).rgb;
#endif
    g.diffuseTransmission = clamp(g.diffuseTransmission, 0.0, 1.0);
    g.diffuseTransmissionColor = clamp(g.diffuseTransmissionColor, 0.0, 1.0);
#endif
    g.sheenColor = sheenColorFactor;
    float sheenRoughness = sheenRoughnessFactor;
#ifdef MAP_SHEEN_COLOR
    g.sheenColor *= lookup(MAP_SHEEN_COLOR).rgb;
#endif
#ifdef MAP_SHEEN_ROUGHNESS
    sheenRoughness *= lookup(MAP_SHEEN_ROUGHNESS).a;
#endif
    g.sheenRoughness = clamp(sheenRoughness, 0.07, 1.0);
    g.clearcoat = clearcoatFactor;
    float clearcoatRoughness = clearcoatRoughnessFactor;
#ifdef MAP_CLEARCOAT
    g.clearcoat *= lookup(MAP_CLEARCOAT).r;
#endif
#ifdef MAP_CLEARCOAT_ROUGHNESS
    clearcoatRoughness *= lookup(MAP_CLEARCOAT_ROUGHNESS).g;
#endif
    g.clearcoatAlpha = clamp(clearcoatRoughness * clearcoatRoughness, 1e-3, 1.0);
    g.iridescence = iridescenceFactor;
#ifdef MAP_IRIDESCENCE
    g.iridescence *= lookup(MAP_IRIDESCENCE).r;
#endif
    g.iridescence = clamp(g.iridescence, 0.0, 1.0);
    g.iridescenceIor = max(iridescenceIor, 1.0);
    g.iridescenceThickness = iridescenceThickness.y;
#ifdef MAP_IRIDESCENCE_THICKNESS
    g.iridescenceThickness = mix(iridescenceThickness.x, iridescenceThickness.y, lookup(MAP_IRIDESCENCE_THICKNESS).g);
#endif
    g.iridescenceThickness = max(g.iridescenceThickness, 0.0);
    return g;
}
