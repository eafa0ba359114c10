// The woven surface shader: core's WovenMaterial::shade lit by lighting.glsl (gltf.frag draws
// every other material). Features a material does not use are compiled out by #defines that the
// C++ side picks from its parameters (woven_gl_material.cpp): WOVEN_NOISE, WOVEN_CRIMP,
// WOVEN_GAPS (both yarns narrower than their element), WOVEN_THREADS (per-thread colours, yarns
// or spacing), WOVEN_SPACING (threads of different widths), WOVEN_TRANSMISSION (yarns that pass
// light, docs/MODEL_TRANSMISSION.md) and WOVEN_FILTER (the far-field weave filter); PREVIEW_SHADOWS (lighting.glsl). A glTF material made woven keeps its surface (core's
// WovenSurfaceMaterial): WOVEN_PRINT (the base colour texture and vertex colour multiply the
// yarns' colour), MAP_BASE_COLOR and MAP_NORMAL in maps[] (texture_maps.glsl), ALPHA_MASK or
// ALPHA_BLEND, as gltf.frag has them.
layout(location = 0) out vec4 outRadiance;

uniform vec3 cameraPosition;
uniform vec3 emission;  // radiance of the front face
#if defined(ALPHA_MASK) || defined(ALPHA_BLEND)
uniform vec4 baseColorFactor;  // its alpha; the colour is the yarns'
uniform float alphaCutoff;
#endif
#ifdef MAP_NORMAL
uniform float normalScale;
#endif
#ifdef WOVEN_FILTER
// The far field's box as a share of the pixel's side (view_refinement.h): where the progressive
// refinement samples the pixel at several points, each stands for its part of the pixel.
uniform float footprintBox;
#endif

// A projection keeps a fair part of its vector, else it is rounding noise (as core).
bool usableProjection(vec3 projected, vec3 original) {
    float l2 = dot(projected, projected);
    return l2 > 1e-10 * dot(original, original) && l2 > 1e-30 && !isinf(l2);
}

// As core's tangentFrame(): x along +u, y along +v, both projected into the plane of n.
Frame tangentFrame(vec3 n, vec3 dpdu, vec3 dpdv) {
    vec3 t = dpdu - dot(dpdu, n) * n;
    vec3 b = dpdv - dot(dpdv, n) * n;
    if (usableProjection(t, dpdu)) {
        vec3 x = normalize(t);
        // y is n x x up to the sign of dp/dv, which stays orthonormal when dp/du and dp/dv
        // are nearly parallel (as core).
        vec3 y = cross(n, x);
        if (usableProjection(b, dpdv) && dot(b, y) < 0.0) y = -y;
        return Frame(x, y, n);
    }
    if (usableProjection(b, dpdv)) {
        vec3 y = normalize(b);
        return Frame(cross(y, n), y, n);
    }
    return frameFromNormal(n);
}

// Light reflected towards wo by a lobe in frame f at p; `ng` as for incidentLight().
vec3 reflectedLight(Frame f, Lobe lobe, vec3 p, vec3 ng, vec3 wo) {
    vec3 woLocal = toLocal(f, wo);
    vec3 sum = ambientSeen * ashikhminShirleyAlbedo(lobe, woLocal, toLocal(f, ng));
    for (int i = 0; i < lightCount; ++i) {
        vec3 wi;
        vec3 L = incidentLight(i, p, ng, wi);
        if (L == vec3(0.0)) continue;  // below the surface, outside a spot's cone, or in shadow
        vec3 wiLocal = toLocal(f, wi);
        sum += ashikhminShirley(lobe, woLocal, wiLocal) * L * max(wiLocal.z, 0.0);
    }
    return sum;
}

// A yarn point as shading sees it (core's YarnLook in WovenMaterial::shade): its lobe with the
// thread's colour, noise and print, its bumped frame, and its transmission t and gloss g.
struct YarnLook {
    Lobe lobe;
    Frame frame;
    float transmission, gloss;
};
YarnLook lookAt(YarnPoint y, Frame tangent, vec3 print) {
    bool weft = y.type == WEFT;
#ifdef WOVEN_THREADS
    vec3 color = threadTexel(weft ? 1 : 0, y.slot, 0).rgb;
    vec4 yarn = yarnTexel(y.yarn, 0), more = yarnTexel(y.yarn, 1);
    float ex = yarn.x, ey = yarn.y, rs = yarn.z, noise = more.y, t = more.z, g = more.w;
#else
    vec3 color = weft ? material.weft_color : material.warp_color;
    float ex = weft ? material.ex : material.warp_ex, ey = weft ? material.ey : material.warp_ey;
    float rs = material.rs, noise = material.noise, t = material.transmission, g = material.transmission_gloss;
#endif
#ifdef WOVEN_NOISE
    uint seed = uint(y.yarnIndex) * 2u + (weft ? 0u : 1u);
    if (noise > 0.0) color = clamp(color * (1.0 + noise * yarnNoise(y.along * material.noise_scale, seed)), 0.0, 1.0);
#endif
    color *= print;
    Frame f = frameFromNormalAndAxis(toWorld(tangent, y.normal), weft ? tangent.x : tangent.y);
    return YarnLook(Lobe(ex, ey, rs, color), f, t, g);
}

// `print` multiplies the yarns' colour, as core's ShadingInput::print.
vec3 yarnRadiance(YarnPoint y, Frame tangent, vec3 p, vec3 ng, vec3 wo, vec3 print) {
    if (y.type == GAP) return reflectedLight(tangent, Lobe(0.0, 0.0, 0.0, material.backing_color), p, ng, wo);
    YarnLook seen = lookAt(y, tangent, print);
    return reflectedLight(seen.frame, seen.lobe, p, ng, wo);
}

#ifdef WOVEN_TRANSMISSION
// The lights behind the cloth (on the side of -ng) that the point passes to wo: as core's
// WovenMaterial::shade, the smaller of both faces' yarns' T through the front face's yarn lobe,
// whichever face is seen (docs/MODEL_TRANSMISSION.md section 3). `other`: the other face's yarn
// at the point, in its tangent frame `otherTangent`.
vec3 transmittedLight(YarnPoint y, Frame tangent, YarnPoint other, Frame otherTangent, bool backSide, vec3 p, vec3 ng,
                      vec3 wo, vec3 print) {
    if (y.type == GAP || other.type == GAP) return vec3(0.0);
    YarnLook seen = lookAt(y, tangent, print);
    if (!(seen.transmission > 0.0)) return vec3(0.0);
    YarnLook behind = lookAt(other, otherTangent, print);
    if (!(behind.transmission > 0.0)) return vec3(0.0);
    vec3 T = min(yarnTransmittance(seen.lobe.rd, seen.transmission), yarnTransmittance(behind.lobe.rd, behind.transmission));
    YarnLook front = backSide ? behind : seen;
    vec3 woLocal = toLocal(front.frame, wo), sum = vec3(0.0);
    for (int i = 0; i < lightCount; ++i) {
        vec3 wi;
        vec3 L = incidentLight(i, p, -ng, wi);
        // As core's TransmittingYarn, the seen yarn's frame parts reflection from transmission,
        // and the cosine is about the transmission frame's normal.
        if (L == vec3(0.0) || dot(wo, seen.frame.z) * dot(wi, seen.frame.z) > 0.0) continue;
        vec3 wiLocal = toLocal(front.frame, wi);
        sum += yarnTransmission(front.lobe, T, front.gloss, woLocal, wiLocal) * L * abs(wiLocal.z);
    }
    // The ambient light from behind, as reflectedLight() takes it from the front: T is what the
    // yarns pass of light from the whole hemisphere behind them (the transmission lobe, diffuse
    // and along the fibres, integrates to it), so a backlit sky shows through as in core.
    return sum + ambientBehind * T;
}
#endif

#ifdef WOVEN_FILTER
// core's far field (core/model/weave_far_field.h, WeaveFarField) for a footprint of whole
// repeats: FILTER_SAMPLES (core's kFarFieldSections, #defined by woven_gl_material.cpp) across
// positions x_k = (k + 1/2) 2 / FILTER_SAMPLES - 1 per yarn, each yarn by the share it covers.
// The reflectance averaged over the weave, for pixels that cover several elements: each yarn
// type weighted by the area it covers, its cross-section sampled uniformly across (crimp and
// noise average out and are left out). Returns radiance x coverage; `coverage` = the opaque
// fraction (1 unless gaps are see-through). Per-thread colours enter as the mean colour of the
// threads the pixel covers on each side, each cell weighted by how much of that side shows in it
// (footprintColors(): a houndstooth's dark warp shows mostly where it is on top) (`footprint`:
// the position and its screen derivatives in threads, as e and de/dx, de/dy); yarn types other than
// the material's own are not averaged: the lobes are the material's warp and weft (an
// approximation for drafts whose yarns differ in exponents or c_y; their widths are in the
// coverage).
// The loop over lights is outermost, so each light's direction and falloff is computed once for
// all 2 x FILTER_SAMPLES frames, not once per frame as reflectedLight() would: that halves the
// default scene's frame time on llvmpipe, with the same result.
#ifdef WOVEN_TRANSMISSION
// The far field's light through the yarns from the lights behind: every covered point passes the
// smaller of the two sides' T (core's WovenMaterial::shade, with the material's own warp and weft
// yarns), through the front face's yarn lobes by the front's yarn areas, the cosine about each
// lobe's own normal. An approximation (core's filtered weave reflects only: core shades a cloth
// whose yarns transmit point by point), so that backlit cloth finer than the pixels still glows.
vec3 averagedTransmission(Frame front, vec3 p, vec3 ng, vec3 wo, Lobe weft, Lobe warp) {
    vec2 weftT, warpT;
    vec3 T = ownYarnsTransmittance(weft, warp, weftT, warpT);
    if (T == vec3(0.0)) return vec3(0.0);
    Frame weftFrame[FILTER_SAMPLES], warpFrame[FILTER_SAMPLES];
    for (int k = 0; k < FILTER_SAMPLES; ++k) {
        float x = (float(k) + 0.5) * (2.0 / float(FILTER_SAMPLES)) - 1.0;
        weftFrame[k] = frameFromNormalAndAxis(toWorld(front, yarnNormal(0, material.cy, x, 0.0)), front.x);
        warpFrame[k] = frameFromNormalAndAxis(toWorld(front, yarnNormal(1, material.cy, x, 0.0)), front.y);
    }
    vec3 sum = vec3(0.0);
    for (int i = 0; i < lightCount; ++i) {
        vec3 wi;
        vec3 L = incidentLight(i, p, -ng, wi);
        if (L == vec3(0.0)) continue;
        vec3 f = vec3(0.0);
        for (int k = 0; k < FILTER_SAMPLES; ++k) {
            vec3 a = toLocal(weftFrame[k], wi), b = toLocal(warpFrame[k], wi);
            f += yarnCoverage.x * yarnTransmission(weft, T, weftT.y, toLocal(weftFrame[k], wo), a) * abs(a.z) +
                 yarnCoverage.y * yarnTransmission(warp, T, warpT.y, toLocal(warpFrame[k], wo), b) * abs(b.z);
        }
        sum += f * L;
    }
    // The ambient light from behind (the sky, the light bounced inside a lampshade) passes as
    // transmittedLight() passes it, through the covered share.
    return sum / float(FILTER_SAMPLES) + ambientBehind * T * (yarnCoverage.x + yarnCoverage.y);
}
#endif

// `front`: the front face's tangent frame (tangent itself where the front is seen).
vec3 averagedRadiance(Frame tangent, Frame front, int face, vec3 p, vec3 ng, vec3 wo, vec2 e, vec2 dedx, vec2 dedy,
                      vec3 print, out float coverage) {
    vec2 yarnArea = face == 0 ? yarnCoverage.xy : yarnCoverage.zw;
    // The pixel's box of elements (whole repeats where the uv cannot resolve it): each side's
    // share as the box shows it.
    vec2 halfBox = 0.5 * (abs(dedx) + abs(dedy));
    bool resolved = dedx.x < 1e29;
    if (resolved) {
        vec3 scales = footprintScales(face, e - halfBox, e + halfBox);
        yarnArea *= scales.yx;
    }
#ifdef WOVEN_THREADS
    vec3 warpColor = footprintColor(warpColorTexture, threadPeriod.x, e.x, dedx.x, dedy.x);
    vec3 weftColor = footprintColor(weftColorTexture, threadPeriod.y, e.y, dedx.y, dedy.y);
    if (resolved) footprintColors(face, e - halfBox, e + halfBox, warpColor, weftColor);
#else
    vec3 weftColor = material.weft_color, warpColor = material.warp_color;
#endif
    Lobe weft = Lobe(material.ex, material.ey, material.rs, weftColor * print);
    Lobe warp = Lobe(material.warp_ex, material.warp_ey, material.rs, warpColor * print);
    Frame weftFrame[FILTER_SAMPLES], warpFrame[FILTER_SAMPLES];
    vec3 weftWo[FILTER_SAMPLES], warpWo[FILTER_SAMPLES];
    vec3 sum = vec3(0.0);
    AlbedoHalfVectors weftH = albedoHalfVectors(weft), warpH = albedoHalfVectors(warp);
    for (int k = 0; k < FILTER_SAMPLES; ++k) {
        float x = (float(k) + 0.5) * (2.0 / float(FILTER_SAMPLES)) - 1.0;
        weftFrame[k] = frameFromNormalAndAxis(toWorld(tangent, yarnNormal(0, material.cy, x, 0.0)), tangent.x);
        warpFrame[k] = frameFromNormalAndAxis(toWorld(tangent, yarnNormal(1, material.cy, x, 0.0)), tangent.y);
        weftWo[k] = toLocal(weftFrame[k], wo);
        warpWo[k] = toLocal(warpFrame[k], wo);
        sum += ambientSeen * (yarnArea.x * ashikhminShirleyAlbedo(weft, weftH, weftWo[k], toLocal(weftFrame[k], ng)) +
                              yarnArea.y * ashikhminShirleyAlbedo(warp, warpH, warpWo[k], toLocal(warpFrame[k], ng)));
    }
    for (int i = 0; i < lightCount; ++i) {
        vec3 wi;
        vec3 L = incidentLight(i, p, ng, wi);
        if (L == vec3(0.0)) continue;
        vec3 f = vec3(0.0);
        for (int k = 0; k < FILTER_SAMPLES; ++k) {
            vec3 weftWi = toLocal(weftFrame[k], wi), warpWi = toLocal(warpFrame[k], wi);
            // No test for a yarn type with no area: its lobe is finite, so it adds 0.
        f += yarnArea.x * ashikhminShirley(weft, weftWo[k], weftWi) * max(weftWi.z, 0.0) +
                 yarnArea.y * ashikhminShirley(warp, warpWo[k], warpWi) * max(warpWi.z, 0.0);
        }
        sum += f * L;
    }
    sum /= float(FILTER_SAMPLES);
#ifdef WOVEN_TRANSMISSION
    sum += averagedTransmission(front, p, ng, wo, weft, warp);
#endif
    coverage = 1.0;
#ifdef WOVEN_GAPS
    float gapArea = max(0.0, 1.0 - yarnArea.x - yarnArea.y);
    if (material.backing != 0) sum += gapArea * reflectedLight(tangent, Lobe(0.0, 0.0, 0.0, material.backing_color), p, ng, wo);
    else coverage = 1.0 - gapArea;
#endif
    return sum;
}
#endif

void main() {
    vec3 p = vPosition;
    vec3 wo = normalize(cameraPosition - p);
    // Derivatives first, while control flow is uniform.
    vec3 dpx = dFdx(p), dpy = dFdy(p);
    vec2 dux = dFdx(vUv), duy = dFdy(vUv);
    vec3 ng = normalize(cross(dpx, dpy));
    if (dot(ng, wo) < 0.0) ng = -ng;
    bool backSide;
    vec3 ns = seenSide(ng, backSide);
#ifdef MAP_NORMAL
    vec3 t, b;
    if (tangentSpace(ns, vTangent, t, b)) ns = normalMapped(ns, t, b, lookup(MAP_NORMAL).xyz, normalScale);
#endif
    vec3 n = backSide ? -ns : ns;
    vec3 radiance = backSide ? vec3(0.0) : emission;

    // dp/du and dp/dv of the triangle: p is an affine function of uv across a triangle, so
    // screen-space differences give them exactly, like core's per-triangle derivatives.
    float det = dux.x * duy.y - duy.x * dux.y;
    vec3 dpdu = vec3(0.0), dpdv = vec3(0.0);
    if (abs(det) > 1e-30) {
        dpdu = (dpx * duy.y - dpy * dux.y) / det;
        dpdv = (dpy * dux.x - dpx * duy.x) / det;
    }
    Frame tangent = tangentFrame(n, dpdu, dpdv);
    int face = backSide ? 1 : 0;

#ifdef WOVEN_FILTER
    // Elements per pixel: from a quarter element on, fade to the averaged reflectance, so no
    // moire appears where the weave is finer than the pixels.
    // A float uv is only known to |uv| 2^-23 (core/model/uv_precision.h): the footprint covers at
    // least that, so a uv too large to resolve a quarter thread shows the far field, as in core.
    vec2 e = vUv * material.repeat, dedx = dux * material.repeat, dedy = duy * material.repeat;
    vec2 spacing = abs(e) * 1.1920929e-7;
    float pixel = max(fwidth(e.x), fwidth(e.y)), unknown = max(spacing.x, spacing.y);
    float farWeight = smoothstep(0.25, 1.0, max(pixel, unknown));
    // Where the spacing passes the pixel's footprint the point is anywhere in it: the mean colour
    // of whole periods (the coarsest mip level), as core's shadeFiltered().
    dedx *= footprintBox;
    dedy *= footprintBox;
    if (unknown > pixel) dedx = vec2(1e30);
#else
    const float farWeight = 0.0;
#endif
    // The glTF base colour's alpha and print, looked up (and cut out) after every derivative.
#if defined(ALPHA_MASK) || defined(ALPHA_BLEND)
    float alpha = baseColorFactor.a * vColor.a;
#endif
#ifdef WOVEN_PRINT
    vec3 print = vColor.rgb;
#else
    const vec3 print = vec3(1.0);
#endif
#ifdef MAP_BASE_COLOR
    vec4 base = lookup(MAP_BASE_COLOR);
#if defined(ALPHA_MASK) || defined(ALPHA_BLEND)
    alpha *= base.a;
#endif
#ifdef WOVEN_PRINT
    print *= base.rgb;
#endif
#endif
#ifdef ALPHA_MASK
    if (alpha < alphaCutoff) discard;
#endif
    vec3 near = vec3(0.0);
    float nearOpacity = 1.0;
    if (farWeight < 1.0) {
        // UVs that do not change across the pixel (a mesh without UVs, or with all of them equal)
        // map no weave: solid cloth, the middle of the first element, as core shades them.
        vec2 uv = det != 0.0 ? vUv : 0.5 / material.repeat;
        YarnPoint y = yarnAt(uv, face);
#ifdef WOVEN_GAPS
        if (y.type == GAP && material.backing == 0) nearOpacity = 0.0;
        else
#endif
        near = yarnRadiance(y, tangent, p, ng, wo, print);
#ifdef WOVEN_TRANSMISSION
        near += transmittedLight(y, tangent, yarnAt(uv, 1 - face), tangentFrame(-n, dpdu, dpdv), backSide, p, ng, wo, print);
#endif
    }
    vec3 far = vec3(0.0);
    float farOpacity = 1.0;
#ifdef WOVEN_FILTER
    if (farWeight > 0.0)
        far = averagedRadiance(tangent, backSide ? tangentFrame(-n, dpdu, dpdv) : tangent, face, p, ng, wo, e, dedx, dedy,
                               print, farOpacity);
#endif
    float opacity = mix(nearOpacity, farOpacity, farWeight);
    // A point shows where the weave covers it and, for BLEND, alpha lets it be seen.
    float coverage = opacity;
#ifdef ALPHA_BLEND
    coverage *= alpha;
#endif
    if (coverage < ditherThreshold()) discard;
    radiance += ((1.0 - farWeight) * nearOpacity * near + farWeight * far) / opacity;
    outRadiance = vec4(radiance, 1.0);
}
