#version 330 core
// Cloth, Gouraud shading: ambient + diffuse + Blinn-Phong specular computed here, per vertex, from the
// smoothed particle normal, once for the front (n) and once for the back (-n); the fragment shader picks
// the side it sees (two-sided lighting).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in float aStrain;
layout(location = 3) in vec2 aUV;

uniform mat4 uViewProj;
uniform vec3 uCameraPos;
uniform vec3 uLightDir;   // unit, towards the light
uniform vec3 uLightColor;
uniform vec3 uAmbient;
uniform float uSpecular;
uniform float uShininess;

out vec3 vFrontDiffuse;
out vec3 vFrontSpecular;
out vec3 vBackDiffuse;
out vec3 vBackSpecular;
out vec2 vUV;
out vec3 vWorld;
out float vStrain;

void lightVertex(vec3 n, vec3 toEye, out vec3 diffuse, out vec3 specular) {
    float ndl = max(dot(n, uLightDir), 0.0);
    vec3 h = normalize(uLightDir + toEye);
    float s = ndl > 0.0 ? pow(max(dot(n, h), 0.0), uShininess) : 0.0;
    diffuse = uAmbient + uLightColor * ndl;
    specular = uLightColor * (uSpecular * s);
}

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
