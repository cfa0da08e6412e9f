#version 330 core
// Cloth, the default view: the fabric (fabric_color.glsl) lit by the Gouraud terms cloth.vert.glsl
// interpolated, for the side seen (fragment_lighting.glsl).
in vec4 vLight;
in vec2 vUV;

#include "fabric_color.glsl"
#include "fragment_lighting.glsl"

out vec4 fragColor;

void main() { fragColor = vec4(shadeTwoSided(fabricColor(vUV), vLight), 1.0); }
