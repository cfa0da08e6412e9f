#version 330 core
// Cloth in the inspection views (the panel's flat shading and strain colours): as cloth.vert.glsl,
// plus the world position (flat shading's face normal) and the spring strain at the particle.
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
