#version 330 core
// Cloth: texture (front; the back a darker shade of it) times the interpolated Gouraud lighting. Flat shading
// lights each fragment with the triangle's own normal instead, from screen-space derivatives.
in vec3 vFrontDiffuse;
in vec3 vFrontSpecular;
in vec3 vBackDiffuse;
in vec3 vBackSpecular;
in vec2 vUV;
in vec3 vWorld;
in float vStrain;

uniform sampler2D uTexture;
uniform bool uUseTexture;
uniform bool uFlat;
uniform bool uStrainColors;
uniform float uStrainMax;  // strain shown as full red (the tear threshold)
uniform vec3 uFrontTint;
uniform vec3 uBackColor;  // textured: multiplies the fabric on the back; else the back's colour
uniform vec3 uCameraPos;
uniform vec3 uLightDir;
uniform vec3 uLightColor;
uniform vec3 uAmbient;
uniform float uSpecular;
uniform float uShininess;

out vec4 fragColor;

// Blue (relaxed) -> green -> yellow -> red (at the tear threshold).
vec3 strainColor(float s) {
    float t = clamp(s, 0.0, 1.0);
    vec3 a = mix(vec3(0.15, 0.25, 0.85), vec3(0.1, 0.8, 0.3), smoothstep(0.0, 0.35, t));
    vec3 b = mix(vec3(0.95, 0.9, 0.15), vec3(0.95, 0.1, 0.08), smoothstep(0.65, 1.0, t));
    return mix(a, b, smoothstep(0.3, 0.7, t));
}

void main() {
    vec3 base;
    if (uStrainColors) base = strainColor(max(vStrain, 0.0) / max(uStrainMax, 1e-6));
    else if (gl_FrontFacing) base = uUseTexture ? texture(uTexture, vUV).rgb * uFrontTint : uFrontTint;
    // The back: the same fabric, duller and darker (uBackColor a shade), as the wrong side of a weave.
    else if (uUseTexture) {
        vec3 fabric = texture(uTexture, vUV).rgb;
        base = mix(vec3(dot(fabric, vec3(0.3, 0.55, 0.15))), fabric, 0.8) * uBackColor;
    } else base = uBackColor;

    vec3 diffuse, specular;
    if (uFlat) {
        // The face normal, turned towards the eye: the visible side is the lit side.
        vec3 n = normalize(cross(dFdx(vWorld), dFdy(vWorld)));
        vec3 toEye = normalize(uCameraPos - vWorld);
        if (dot(n, toEye) < 0.0) n = -n;
        float ndl = max(dot(n, uLightDir), 0.0);
        vec3 h = normalize(uLightDir + toEye);
        float s = ndl > 0.0 ? pow(max(dot(n, h), 0.0), uShininess) : 0.0;
        diffuse = uAmbient + uLightColor * ndl;
        specular = uLightColor * (uSpecular * s);
    } else if (gl_FrontFacing) {
        diffuse = vFrontDiffuse;
        specular = vFrontSpecular;
    } else {
        diffuse = vBackDiffuse;
        specular = vBackSpecular;
    }
    fragColor = vec4(base * diffuse + specular, 1.0);
}
