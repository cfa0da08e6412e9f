#version 330 core
// The fringe of loose threads along torn edges (render_mesh.h FringeMesh): lit per vertex as the
// cloth is (shaders/cloth.vert.glsl), front and back; the threads themselves are cut out in the
// fragment shader.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUV;
layout(location = 3) in float aThread; // thread coordinate along the edge: one unit per woven thread
layout(location = 4) in float aAcross; // 0 at the torn edge, 1 at the fringe's outer edge

uniform mat4 uViewProj;
#include "vertex_lighting.glsl"

out vec4 vLight;
out vec2 vUV;
out float vThread;
out float vAcross;

void main() {
    vLight = lightTwoSided(normalize(aNormal), normalize(uCameraPos - aPosition));
    vUV = aUV;
    vThread = aThread;
    vAcross = aAcross;
    gl_Position = uViewProj * vec4(aPosition, 1.0);
}
