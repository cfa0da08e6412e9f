#version 330 core
// Cloth, Gouraud shading (the default view): the lighting terms of both sides per vertex, from the
// smoothed particle normal; the fragment shader picks the side it sees (two-sided lighting). The flat
// and strain views use cloth_inspect.*.glsl, which interpolate more.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 3) in vec2 aUV;

uniform mat4 uViewProj;
#include "vertex_lighting.glsl"

out vec4 vLight;
out vec2 vUV;

void main() {
    vLight = lightTwoSided(normalize(aNormal), normalize(uCameraPos - aPosition));
    vUV = aUV;
    gl_Position = uViewProj * vec4(aPosition, 1.0);
}
