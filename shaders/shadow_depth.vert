// Depth pass of ShadowMaps (app/preview/shadow_maps.cpp).
layout(location = 0) in vec3 position;
layout(location = 6) in mat4 instanceMatrix;  // as mesh.vert's

uniform mat4 viewProjection;

out vec3 vWorld;

void main() {
    vWorld = (instanceMatrix * vec4(position, 1.0)).xyz;
    gl_Position = viewProjection * vec4(vWorld, 1.0);
}
