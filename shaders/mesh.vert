// World-space meshes: the scene description's vertices are already in world space. Attributes
// a mesh lacks are zero (uv1, tangent) or white (colour).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;
layout(location = 3) in vec2 uv1;
layout(location = 4) in vec4 color;
layout(location = 5) in vec4 tangent;

uniform mat4 viewProjection;

out vec3 vPosition;
out vec3 vNormal;
out vec2 vUv;
out vec2 vUv1;
out vec4 vColor;
out vec4 vTangent;

void main() {
    vPosition = position;
    vNormal = normal;
    vUv = uv;
    vUv1 = uv1;
    vColor = color;
    vTangent = tangent;
    gl_Position = viewProjection * vec4(position, 1.0);
}
