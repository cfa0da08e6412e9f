#version 330 core
// The ground's colour (ground.frag.glsl's formula) darkened by the cloth above it: dark where the
// cloth touches the ground (a contact shadow), gone 1 m up. Blended with
// GL_MIN over the ground, so that where the cloth is folded over itself the shadow is the darkest
// layer's, not the layers multiplied.
in vec3 vWorld;
in float vAbove;

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
    float darkness = 0.5 * exp(-vAbove / 0.25); // 0.5 at contact, 0.01 at 1 m (the pass stops there)
    vec3 lit = uColor * checker * (uAmbient + uLightColor * max(uLightDir.y, 0.0)) * (1.0 - darkness);
    vec3 d = vWorld - uCameraPos;
    float fade = clamp(dot(d, d) / (uFadeDistance * uFadeDistance), 0.0, 1.0);
    fragColor = vec4(mix(lit, uSky, fade), 1.0);
}
