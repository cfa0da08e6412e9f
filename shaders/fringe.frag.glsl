#version 330 core
// Loose threads along a torn edge, alpha-tested: thread k (floor of the thread coordinate) sticks out
// of the edge by its own length (35 to 100 % of the strip), slanted and thinning to its tip, in the
// fabric's colour at the edge (a little lighter or darker per thread: cut ends catch the light).
in vec4 vLight;
in vec2 vUV;
in float vThread;
in float vAcross;

uniform sampler2D uTexture;
uniform bool uUseTexture;
uniform vec3 uFrontTint;
uniform vec3 uBackColor; // the back: the same fabric times this shade (fabric_color.glsl)
#include "fragment_lighting.glsl"

out vec4 fragColor;

float hash(float k) { return fract(sin(k * 12.9898) * 43758.5453); }

void main() {
    float k = floor(vThread);
    float reach = 0.35 + 0.65 * hash(k);
    if (vAcross > reach) discard;
    float t = vAcross / reach;                        // 0 at the edge, 1 at this thread's tip
    float slant = (hash(k + 17.0) - 0.5) * 0.8;       // in thread spacings at the tip
    float x = fract(vThread) - 0.5 - slant * t * t;   // across the thread, curling towards its tip
    float halfWidth = 0.24 * (1.0 - 0.6 * t);
    if (abs(x) > halfWidth) discard;

    vec3 fabric = uUseTexture ? texture(uTexture, vUV).rgb : vec3(1.0);
    float shade = 0.85 + 0.3 * hash(k + 5.0);
    vec3 base = fabric * shade * (gl_FrontFacing ? uFrontTint : uBackColor);
    fragColor = vec4(shadeTwoSided(base, vLight), 1.0);
}
