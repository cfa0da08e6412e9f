#version 330 core
// Cloth, Gouraud shading: the lighting terms of both sides per vertex, from the smoothed particle
// normal; the fragment shader picks the side it sees (two-sided lighting). The default view's
// fragment shader (cloth.frag.glsl) reads only vLight and vUV, and the linker drops the outputs no
// stage reads, so only those are interpolated; the flat and strain views (cloth_inspect.frag.glsl)
// read the world position and the strain too.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in float aStrain;
layout(location = 3) in vec2 aUV;

uniform mat4 uViewProj;
#include "vertex_lighting.glsl"

out vec4 vLight;
out vec2 vUV;
out vec3 vWorld;
out float vStrain;

void main() {
    vLight = lightTwoSided(normalize(aNormal), normalize(uCameraPos - aPosition));
    vUV = aUV;
    vWorld = aPosition;
    vStrain = aStrain;
    gl_Position = uViewProj * vec4(aPosition, 1.0);
}
