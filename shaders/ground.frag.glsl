#version 330 core
// Ground: 1 m checker tiles lit from above, fading into the sky colour with distance. Kept cheap: with
// a software renderer the ground covers half the screen.
in vec3 vWorld;

#include "ground_color.glsl"

out vec4 fragColor;

void main() {
    fragColor = vec4(groundColor(vWorld, 0.0), 1.0);
}
