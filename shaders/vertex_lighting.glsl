// Gouraud lighting of one vertex, both sides (included by the cloth and fringe vertex shaders): for
// the normal n and -n, the diffuse term n.l and the Blinn-Phong specular term, seen along toEye.
// Only these four numbers are interpolated across a triangle; fragment_lighting.glsl turns the side it
// sees into a colour with the light's colours. Interpolating the colours instead (two vec3 a side)
// made llvmpipe set up 12 floats per triangle instead of 4: at 256 x 256 a third of the cloth's draw.
uniform vec3 uCameraPos;
uniform vec3 uLightDir;   // unit, towards the light
uniform float uShininess;

vec2 lightTerms(vec3 n, vec3 toEye) {
    float ndl = max(dot(n, uLightDir), 0.0);
    vec3 h = normalize(uLightDir + toEye);
    float s = ndl > 0.0 ? pow(max(dot(n, h), 0.0), uShininess) : 0.0;
    return vec2(ndl, s);
}

// xy: the front (n), zw: the back (-n).
vec4 lightTwoSided(vec3 n, vec3 toEye) { return vec4(lightTerms(n, toEye), lightTerms(-n, toEye)); }
