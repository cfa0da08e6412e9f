#version 330 core
// Ground: 1 m checker tiles lit from above, fading into the sky colour with distance. Kept cheap: with
// a software renderer the ground covers half the screen.
in vec3 vWorld;

uniform vec3 uColor;
uniform vec3 uSky;
uniform vec3 uCameraPos;
uniform vec3 uLightDir;
uniform vec3 uLightColor;
uniform vec3 uAmbient;
uniform float uFadeDistance;

out vec4 fragColor;

void main() {
    vec2 cell = floor(vWorld.xz);
    float checker = 1.0 - 0.14 * mod(cell.x + cell.y, 2.0);
    vec3 lit = uColor * checker * (uAmbient + uLightColor * max(uLightDir.y, 0.0));
    vec3 d = vWorld - uCameraPos;
    float fade = clamp(dot(d, d) / (uFadeDistance * uFadeDistance), 0.0, 1.0);
    fragColor = vec4(mix(lit, uSky, fade), 1.0);
}
