// Transmittance pass of ShadowMaps for a woven material whose yarns let light through
// (WOVEN_TRANSMISSION) or whose gaps do (WOVEN_GAPS, no backing): per colour, the share of a
// light's beam that crosses the cloth, which lighting.glsl multiplies into that light where a
// point lies behind it. The weave is averaged
// as the far field averages it (woven.frag's averagedTransmission): a shadow-map texel spans
// about a thread or more, and the shadow of a point lookup would alias. The crossing yarns pass
// the smaller of the own warp's and weft's T through the front's yarn areas (yarnCoverage.xy),
// each by yarnTransmittedAlbedo() at the light's cosine to the sheet; see-through gaps pass
// everything; the yarn bumps, noise and a kept glTF surface's print are left out.
layout(location = 0) out vec4 outTransmittance;

void main() {
    vec3 p = vPosition;
    gl_FragDepth = shadowDepth(p);
    vec3 through = vec3(0.0);
#ifdef WOVEN_TRANSMISSION
    vec3 ng = cross(dFdx(p), dFdy(p));
    float mu = dot(ng, ng) > 0.0 ? abs(dot(normalize(ng), towardsShadowLight(p))) : 1.0;
#ifdef WOVEN_THREADS
    // The mean colour of whole periods (the coarsest level of the colour tracks).
    vec3 warpColor = footprintColor(warpColorTexture, threadPeriod.x, 0.0, 1e30, 1e30);
    vec3 weftColor = footprintColor(weftColorTexture, threadPeriod.y, 0.0, 1e30, 1e30);
#else
    vec3 weftColor = material.weft_color, warpColor = material.warp_color;
#endif
    Lobe weft = Lobe(material.ex, material.ey, material.rs, weftColor);
    Lobe warp = Lobe(material.warp_ex, material.warp_ey, material.rs, warpColor);
    vec2 weftT, warpT;
    vec3 T = ownYarnsTransmittance(weft, warp, weftT, warpT);
    through = yarnCoverage.x * yarnTransmittedAlbedo(weft, T, mu) + yarnCoverage.y * yarnTransmittedAlbedo(warp, T, mu);
#endif
#ifdef WOVEN_GAPS
    if (material.backing == 0) through += vec3(max(0.0, 1.0 - yarnCoverage.x - yarnCoverage.y));
#endif
    outTransmittance = vec4(through, 1.0);
}
