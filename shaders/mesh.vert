// A mesh's vertices placed in world space by instanceMatrix: an instanced mesh's copy's matrix
// (gpu_mesh.h), the identity for any other mesh, whose vertices are already there (the identity
// changes no value). Normals go by the inverse transpose, tangents by the matrix, the handedness
// turns with a mirroring copy, as core places a copy's hit (render_scene.cpp's hitCorners).
// Attributes a mesh lacks are zero (uv1, tangent) or white (colour). skyVisibility: the sky's
// share about the normal and about its opposite (app/preview/sky_visibility.h); bounced and
// offCloth: the light bounced to each side (app/preview/bounced_light.h), that off woven cloth
// times the albedo of the faces it left here (a: the share off front faces); lightsSeen: which of
// the first lights the vertex sees.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;
layout(location = 3) in vec2 uv1;
layout(location = 4) in vec4 color;
layout(location = 5) in vec4 tangent;
layout(location = 6) in mat4 instanceMatrix;  // locations 6 to 9
layout(location = 10) in vec2 skyVisibility;
layout(location = 11) in vec3 bouncedFront;
layout(location = 12) in vec3 bouncedBack;
layout(location = 13) in vec4 offClothFront;
layout(location = 14) in vec4 offClothBack;
layout(location = 15) in uvec2 lightsSeen;  // a byte a light, 255: seen (bounced_light.h)

uniform mat4 viewProjection;
uniform vec3 bouncedClothFront, bouncedClothBack;  // the woven cloth's albedo on each face

out vec3 vPosition;
out vec3 vNormal;
out vec2 vUv;
out vec2 vUv1;
out vec4 vColor;
out vec4 vTangent;
out vec2 vSkyVisibility;
out vec3 vBouncedFront, vBouncedBack;
out vec4 vLightsSeen[2];

vec4 unpackBytes(uint word) { return vec4(uvec4(word, word >> 8u, word >> 16u, word >> 24u) & 255u) / 255.0; }

vec3 offCloth(vec4 light) { return mix(bouncedClothBack, bouncedClothFront, light.a) * light.rgb; }

void main() {
    mat3 linear = mat3(instanceMatrix);
    vPosition = (instanceMatrix * vec4(position, 1.0)).xyz;
    vNormal = transpose(inverse(linear)) * normal;
    vUv = uv;
    vUv1 = uv1;
    vColor = color;
    vSkyVisibility = skyVisibility;
    vBouncedFront = bouncedFront + offCloth(offClothFront);
    vBouncedBack = bouncedBack + offCloth(offClothBack);
    vLightsSeen[0] = unpackBytes(lightsSeen.x);
    vLightsSeen[1] = unpackBytes(lightsSeen.y);
    vTangent = vec4(linear * tangent.xyz, determinant(linear) < 0.0 ? -tangent.w : tangent.w);
    gl_Position = viewProjection * vec4(vPosition, 1.0);
}
