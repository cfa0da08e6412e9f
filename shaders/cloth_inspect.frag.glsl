#version 330 core
// Cloth in the inspection views: strain colours (blue relaxed to red at the tear threshold) lit as the
// cloth is, and/or flat shading, which lights each fragment with its triangle's own normal from
// screen-space derivatives instead of the interpolated vertex lighting.
in vec4 vLight;
in vec2 vUV;
in vec3 vWorld;
in float vStrain;

uniform bool uFlat;
uniform bool uStrainColors;
uniform float uStrainMax;  // strain shown as full red (the tear threshold)
#include "vertex_lighting.glsl"
#include "fabric_color.glsl"
#include "fragment_lighting.glsl"

out vec4 fragColor;

// Blue (relaxed) -> green -> yellow -> red (at the tear threshold).
vec3 strainColor(float s) {
    float t = clamp(s, 0.0, 1.0);
    vec3 a = mix(vec3(0.15, 0.25, 0.85), vec3(0.1, 0.8, 0.3), smoothstep(0.0, 0.35, t));
    vec3 b = mix(vec3(0.95, 0.9, 0.15), vec3(0.95, 0.1, 0.08), smoothstep(0.65, 1.0, t));
    return mix(a, b, smoothstep(0.3, 0.7, t));
}

void main() {
    vec3 base = uStrainColors ? strainColor(max(vStrain, 0.0) / max(uStrainMax, 1e-6)) : fabricColor(vUV);
    if (!uFlat) {
        fragColor = vec4(shadeTwoSided(base, vLight), 1.0);
        return;
    }
    // The face normal, turned towards the eye: the visible side is the lit side.
    vec3 n = normalize(cross(dFdx(vWorld), dFdy(vWorld)));
    vec3 toEye = normalize(uCameraPos - vWorld);
    if (dot(n, toEye) < 0.0) n = -n;
    fragColor = vec4(shadeLit(base, lightTwoSided(n, toEye).xy), 1.0);
}
