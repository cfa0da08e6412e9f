#version 330 core
// Balls: a unit sphere scaled and moved by uModel, Gouraud-lit per vertex like the cloth.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;

uniform mat4 uViewProj;
uniform mat4 uModel;
uniform vec3 uCameraPos;
uniform vec3 uLightDir;
uniform vec3 uLightColor;
uniform vec3 uAmbient;
uniform float uSpecular;
uniform float uShininess;
uniform vec3 uColor;

out vec3 vColor;

void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vec3 n = normalize(mat3(uModel) * aNormal);
    vec3 toEye = normalize(uCameraPos - world.xyz);
    float ndl = max(dot(n, uLightDir), 0.0);
    vec3 h = normalize(uLightDir + toEye);
    float s = ndl > 0.0 ? pow(max(dot(n, h), 0.0), uShininess * 2.0) : 0.0;
    vColor = uColor * (uAmbient + uLightColor * ndl) + uLightColor * (uSpecular * 2.0 * s);
    gl_Position = uViewProj * world;
}
