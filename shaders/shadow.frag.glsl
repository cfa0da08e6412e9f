#version 330 core
// The ground's colour (ground_color.glsl) darkened by the cloth above it: dark where the cloth
// touches the ground (a contact shadow), gone 1 m up. Blended with GL_MIN over the ground, so that
// where the cloth is folded over itself the shadow is the darkest layer's, not the layers multiplied.
in vec3 vWorld;
in float vAbove;

#include "ground_color.glsl"

out vec4 fragColor;

void main() {
    float darkness = 0.5 * exp(-vAbove / 0.25); // 0.5 at contact, 0.01 at 1 m (the pass stops there)
    fragColor = vec4(groundColor(vWorld, darkness), 1.0);
}
