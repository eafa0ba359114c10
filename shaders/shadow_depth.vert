// Depth pass of ShadowMaps (app/preview/shadow_maps.cpp).
layout(location = 0) in vec3 position;

uniform mat4 viewProjection;

out vec3 vWorld;

void main() {
    vWorld = position;
    gl_Position = viewProjection * vec4(position, 1.0);
}
