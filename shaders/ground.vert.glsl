#version 330 core
// The ground: one large quad at y = uHeight, centred under the camera target.
layout(location = 0) in vec2 aCorner; // [-1, 1]^2

uniform mat4 uViewProj;
uniform float uHeight;
uniform vec2 uCenter;
uniform float uExtent;

out vec3 vWorld;

void main() {
    vWorld = vec3(uCenter.x + aCorner.x * uExtent, uHeight, uCenter.y + aCorner.y * uExtent);
    gl_Position = uViewProj * vec4(vWorld, 1.0);
}
