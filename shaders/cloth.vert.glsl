#version 330 core
// Cloth, Gouraud shading: ambient + diffuse + Blinn-Phong specular computed here, per vertex, from the
// smoothed particle normal, once for the front (n) and once for the back (-n); the fragment shader picks
// the side it sees (two-sided lighting).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in float aStrain;
layout(location = 3) in vec2 aUV;

uniform mat4 uViewProj;
#include "vertex_lighting.glsl"

out vec3 vFrontDiffuse;
out vec3 vFrontSpecular;
out vec3 vBackDiffuse;
out vec3 vBackSpecular;
out vec2 vUV;
out vec3 vWorld;
out float vStrain;

void main() {
    vec3 n = normalize(aNormal);
    vec3 toEye = normalize(uCameraPos - aPosition);
    lightVertex(n, toEye, vFrontDiffuse, vFrontSpecular);
    lightVertex(-n, toEye, vBackDiffuse, vBackSpecular);
    vUV = aUV;
    vWorld = aPosition;
    vStrain = aStrain;
    gl_Position = uViewProj * vec4(aPosition, 1.0);
}
