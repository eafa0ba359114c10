// World-space meshes: the scene description's vertices are already in world space.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;

uniform mat4 viewProjection;

out vec3 vPosition;
out vec3 vNormal;
out vec2 vUv;

void main() {
    vPosition = position;
    vNormal = normal;
    vUv = uv;
    gl_Position = viewProjection * vec4(position, 1.0);
}
