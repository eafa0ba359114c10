// core's normal_map.h: glTF's tangent-space normal map, for gltf.frag and for a glTF material
// made woven (woven.frag), whose weave bumps the mapped normal further.

// The tangent and bitangent of the file's normal `ns` from the mesh's tangent (handedness from
// its w, as core); false, and both zero, where the mesh gives none.
bool tangentSpace(vec3 ns, vec4 tangent, out vec3 t, out vec3 b) {
    t = tangent.xyz - dot(tangent.xyz, ns) * ns;
    bool usable = dot(t, t) > 1e-20;
    t = usable ? normalize(t) : vec3(0.0);
    b = (tangent.w < 0.0 ? -1.0 : 1.0) * cross(ns, t);
    return usable;
}

// A normal texel (in [0, 1]) with its scale applied in the frame (t, b, ns); ns where degenerate.
vec3 normalMapped(vec3 ns, vec3 t, vec3 b, vec3 texel, float scale) {
    vec3 m = texel * 2.0 - 1.0;
    vec3 perturbed = m.x * scale * t + m.y * scale * b + m.z * ns;
    return dot(perturbed, perturbed) > 1e-20 ? normalize(perturbed) : ns;
}
