#version 330 core
// Cloth: the fabric (cloth.vert.glsl) times the interpolated Gouraud lighting of the side seen.
in vec4 vLight;
in vec2 vUV;

#include "fabric_color.glsl"
#include "fragment_lighting.glsl"

out vec4 fragColor;

void main() { fragColor = vec4(shadeTwoSided(fabricColor(vUV), vLight), 1.0); }
