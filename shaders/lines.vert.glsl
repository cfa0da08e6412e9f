#version 330 core
// Debug overlays: springs as lines, weak and pinned particles as points.
layout(location = 0) in vec3 aPosition;
uniform mat4 uViewProj;
uniform float uPointSize;
void main() {
    gl_Position = uViewProj * vec4(aPosition, 1.0);
    gl_PointSize = uPointSize;
}
