#version 330 core
// The cloth's soft shadow on the ground: its triangles again (the cloth's own buffers), each vertex
// pushed down onto the ground plane (leaning towards the light), remembering how high it was.
layout(location = 0) in vec3 aPosition;

uniform mat4 uViewProj;
uniform vec3 uLightDir; // unit, towards the light
uniform float uHeight;  // the ground's y

out vec3 vWorld;
out float vAbove;

void main() {
    float above = max(aPosition.y - uHeight, 0.0);
    // Down, leaning a little along the light (at most 0.6 m): a contact shadow, under what casts it.
    float along = min(above / max(uLightDir.y, 0.2), 0.6);
    vWorld = vec3(aPosition.x, uHeight, aPosition.z) - vec3(uLightDir.x, 0.0, uLightDir.z) * along;
    vAbove = above;
    gl_Position = uViewProj * vec4(vWorld, 1.0);
}
