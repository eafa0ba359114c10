// core/bsdf/gltf_bxdf.cpp's eval() in GLSL (reflection, and KHR_materials_diffuse_transmission's
// Lambertian BTDF for lights behind the surface; the preview draws thin transmission as partial
// coverage): Lambert + GGX (anisotropic) with the height-correlated Smith term, dielectric
// and metal Fresnel, the Charlie sheen layer with its albedo scaling (the albedo table is core's,
// uploaded as a texture), the clearcoat layer and the iridescent film (gltf_iridescence.glsl). Local frame: z = the shading normal, x = the
// anisotropy direction.
struct GltfInputs {
    vec3 baseColor;
    float metallic;
    float alphaX, alpha;       // alpha = roughness^2 (along y), alphaX = mix(alpha, 1, anisotropy^2), clamped as core
    vec3 f0;                   // dielectric F0 (KHR_materials_ior, KHR_materials_specular)
    float f90;
    float transmission;
    float diffuseTransmission;      // KHR_materials_diffuse_transmission's factor x texture
    vec3 diffuseTransmissionColor;
    vec3 sheenColor;
    float sheenRoughness;      // clamped to [0.07, 1] as core's SheenLobe
    float clearcoat, clearcoatAlpha;
    float iridescence, iridescenceIor, iridescenceThickness;  // strength, film IOR, nm
};

// The dielectric's (xyz) and the metal's Fresnel at cosTheta to the microfacet normal, as core's
// GltfBxdf::fresnel(): Schlick's, mixed towards the film's by the iridescence.
void gltfFresnel(GltfInputs g, float cosTheta, out vec3 dielectric, out vec3 metal) {
    float weight = pow5(clamp(1.0 - cosTheta, 0.0, 1.0));
    dielectric = g.f0 + (vec3(g.f90) - g.f0) * weight;
    metal = g.baseColor + (1.0 - g.baseColor) * weight;
    if (g.iridescence > 0.0) {
        float outside = 1.0 + 0.5 * g.clearcoat;  // the coat's 1.5 as far as it covers the film
        dielectric = mix(dielectric, thinFilmFresnel(outside, g.iridescenceIor, cosTheta, g.iridescenceThickness, g.f0), g.iridescence);
        metal = mix(metal, thinFilmFresnel(outside, g.iridescenceIor, cosTheta, g.iridescenceThickness, g.baseColor), g.iridescence);
    }
}

uniform sampler2D sheenAlbedoTable;  // SheenLobe::albedoTable(): x = cos theta, y = roughness

float ggxD(float ax, float ay, vec3 h) {
    if (h.z <= 0.0) return 0.0;
    float a2 = ax * ay;
    vec3 f = vec3(ay * h.x, ax * h.y, a2 * h.z);
    float w2 = a2 / dot(f, f);
    return a2 * w2 * w2 / PI;
}

float ggxVisibility(float ax, float ay, vec3 wo, vec3 wi) {
    if (!(wo.z > 0.0) || !(wi.z > 0.0)) return 0.0;
    return 0.5 / (wi.z * length(vec3(ax * wo.x, ay * wo.y, wo.z)) + wo.z * length(vec3(ax * wi.x, ay * wi.y, wi.z)));
}

float sheenFitL(float x, float alpha) {
    float t = (1.0 - alpha) * (1.0 - alpha);
    float a = mix(21.5473, 25.3245, t), b = mix(3.82987, 3.32435, t), c = mix(0.19823, 0.16801, t);
    float d = mix(-1.97760, -1.27393, t), e = mix(-4.32054, -4.85967, t);
    return a / (1.0 + b * pow(x, c)) + d * x + e;
}

float sheenLambda(float cosTheta, float alpha) {
    float c = abs(cosTheta);
    return c < 0.5 ? exp(sheenFitL(c, alpha)) : exp(2.0 * sheenFitL(0.5, alpha) - sheenFitL(1.0 - c, alpha));
}

float sheenAlbedo(float cosTheta, float roughness) {
    const float N = 32.0;
    vec2 at = (vec2(clamp(cosTheta, 0.0, 1.0), roughness) * (N - 1.0) + 0.5) / N;
    return texture(sheenAlbedoTable, at).r;
}

float coatFresnel(float cosTheta) { return 0.04 + 0.96 * pow5(clamp(1.0 - cosTheta, 0.0, 1.0)); }

vec3 gltfBsdf(GltfInputs g, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0 || wi.z <= 0.0) return vec3(0.0);
    vec3 H = wo + wi;
    float len = length(H);
    if (!(len > 1e-12)) return vec3(0.0);
    vec3 h = H / len;
    vec3 dielectricF, metalF;
    gltfFresnel(g, 0.5 * len, dielectricF, metalF);
    float specular = ggxD(g.alphaX, g.alpha, h) * ggxVisibility(g.alphaX, g.alpha, wo, wi);
    vec3 dielectric = (1.0 - dielectricF) * (1.0 - g.transmission) * (1.0 - g.diffuseTransmission) * g.baseColor / PI +
                      dielectricF * specular;
    vec3 metal = metalF * specular;
    vec3 f = mix(dielectric, metal, g.metallic);
    float sheenMax = max(g.sheenColor.r, max(g.sheenColor.g, g.sheenColor.b));
    if (sheenMax > 0.0) {
        float sheenAlpha = g.sheenRoughness * g.sheenRoughness;
        float scaleO = clamp(1.0 - sheenMax * sheenAlbedo(wo.z, g.sheenRoughness), 0.0, 1.0);
        float scaleI = clamp(1.0 - sheenMax * sheenAlbedo(wi.z, g.sheenRoughness), 0.0, 1.0);
        float sin2 = min(h.x * h.x + h.y * h.y, 1.0);
        float D = (2.0 + 1.0 / sheenAlpha) * pow(sin2, 0.5 / sheenAlpha) / (2.0 * PI);
        float V = 1.0 / ((1.0 + sheenLambda(wo.z, sheenAlpha) + sheenLambda(wi.z, sheenAlpha)) * (4.0 * wo.z * wi.z));
        f = f * min(scaleO, scaleI) + g.sheenColor * D * V;
    }
    if (g.clearcoat > 0.0) {
        float coat = g.clearcoat * coatFresnel(0.5 * len) * ggxD(g.clearcoatAlpha, g.clearcoatAlpha, h) *
                     ggxVisibility(g.clearcoatAlpha, g.clearcoatAlpha, wo, wi);
        f = f * (1.0 - g.clearcoat * max(coatFresnel(wo.z), coatFresnel(wi.z))) + vec3(coat);
    }
    return f;
}

// The diffuse transmission towards wo of light from wi on the other side (wi.z < 0), as core's
// eval(): Fresnel at the half vector of wo and wi mirrored, the sheen's and the coat's scaling of
// the layer below at |wi.z|.
vec3 gltfDiffuseBtdf(GltfInputs g, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0 || wi.z >= 0.0) return vec3(0.0);
    vec3 w = vec3(wi.xy, -wi.z);
    float len = length(wo + w);
    vec3 dielectricF, metalF;
    gltfFresnel(g, 0.5 * len, dielectricF, metalF);
    vec3 f = (1.0 - g.metallic) * (1.0 - g.transmission) * g.diffuseTransmission / PI * (1.0 - dielectricF) *
             g.diffuseTransmissionColor;
    float sheenMax = max(g.sheenColor.r, max(g.sheenColor.g, g.sheenColor.b));
    if (sheenMax > 0.0) {
        float scaleO = clamp(1.0 - sheenMax * sheenAlbedo(wo.z, g.sheenRoughness), 0.0, 1.0);
        float scaleI = clamp(1.0 - sheenMax * sheenAlbedo(w.z, g.sheenRoughness), 0.0, 1.0);
        f *= min(scaleO, scaleI);
    }
    if (g.clearcoat > 0.0) f *= 1.0 - g.clearcoat * max(coatFresnel(wo.z), coatFresnel(w.z));
    return f;
}

// Karis's fit of GGX's split-sum environment terms: reflectance = F0 * x + F90 * y.
vec2 ggxAlbedoTerms(float roughness, float cosO) {
    const vec4 c0 = vec4(-1.0, -0.0275, -0.572, 0.022);
    const vec4 c1 = vec4(1.0, 0.0425, 1.04, -0.04);
    vec4 r = roughness * c0 + c1;
    float a004 = min(r.x * r.x, exp2(-9.28 * cosO)) * r.x + r.y;
    return vec2(-1.04, 1.04) * a004 + r.zw;
}

// The BSDF's reflectance towards wo under uniform light (the preview's ambient term), with the
// same layering as gltfBsdf(); an anisotropic lobe as the isotropic one of the mean alpha.
vec3 gltfAlbedo(GltfInputs g, float cosO) {
    if (cosO <= 0.0) return vec3(0.0);
    vec2 terms = ggxAlbedoTerms(sqrt(sqrt(g.alphaX * g.alpha)), cosO);
    vec3 dielectricSpec = g.f0 * terms.x + g.f90 * terms.y;
    vec3 metal = g.baseColor * terms.x + terms.y;
    if (g.iridescence > 0.0) {
        // What the film adds to the Fresnel towards the view, scaled by the split sum's x + y
        // (its albedo for a Fresnel of 1), as glTF viewers light the film.
        vec3 filmDielectric, filmMetal, plainDielectric, plainMetal;
        gltfFresnel(g, cosO, filmDielectric, filmMetal);
        GltfInputs plain = g;
        plain.iridescence = 0.0;
        gltfFresnel(plain, cosO, plainDielectric, plainMetal);
        dielectricSpec += (filmDielectric - plainDielectric) * (terms.x + terms.y);
        metal += (filmMetal - plainMetal) * (terms.x + terms.y);
    }
    // A constant ambient lights the other side as much: the diffuse transmission passes its share.
    vec3 diffuse = (1.0 - g.diffuseTransmission) * g.baseColor + g.diffuseTransmission * g.diffuseTransmissionColor;
    vec3 dielectric = (1.0 - dielectricSpec) * (1.0 - g.transmission) * diffuse + dielectricSpec;
    vec3 albedo = mix(dielectric, metal, g.metallic);
    float sheenMax = max(g.sheenColor.r, max(g.sheenColor.g, g.sheenColor.b));
    if (sheenMax > 0.0) {
        float e = sheenAlbedo(cosO, g.sheenRoughness);
        albedo = albedo * clamp(1.0 - sheenMax * e, 0.0, 1.0) + g.sheenColor * e;
    }
    if (g.clearcoat > 0.0) {
        vec2 coat = ggxAlbedoTerms(sqrt(g.clearcoatAlpha), cosO);
        albedo = albedo * (1.0 - g.clearcoat * coatFresnel(cosO)) + g.clearcoat * (0.04 * coat.x + coat.y);
    }
    return albedo;
}
