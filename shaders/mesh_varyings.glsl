// What mesh.vert hands every surface shader, interpolated: world-space position and normal, both
// sets of texture coordinates, the vertex colour and the tangent (zero or white where the mesh
// has none), the sky's share on the normal's side and on the other (sky_visibility.h), and the
// radiance bounced to either side and the share of each of the first lights the vertex sees
// (bounced_light.h).
in vec3 vPosition;
in vec3 vNormal;
in vec2 vUv;
in vec2 vUv1;
in vec4 vColor;
in vec4 vTangent;
in vec2 vSkyVisibility;
in vec3 vBouncedFront, vBouncedBack;
in vec4 vLightsSeen[2];  // light i: [i / 4][i % 4], 1 seen, 0 blocked (VERTEX_SHADOW_LIGHTS)
