#version 330 core
// Ground: 1 m checker tiles, lit from above, fading into the sky colour with distance.
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
    float checker = mod(cell.x + cell.y, 2.0) < 0.5 ? 1.0 : 0.86;
    // Thin grid lines every metre.
    vec2 f = abs(fract(vWorld.xz) - 0.5);
    float line = smoothstep(0.485, 0.5, max(f.x, f.y));
    vec3 lit = uColor * checker * (uAmbient + uLightColor * max(uLightDir.y, 0.0));
    lit = mix(lit, lit * 0.75, line);
    float fade = smoothstep(0.35 * uFadeDistance, uFadeDistance, length(vWorld - uCameraPos));
    fragColor = vec4(mix(lit, uSky, fade), 1.0);
}
