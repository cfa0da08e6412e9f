// Gouraud lighting of one vertex, both sides (included by the cloth and fringe vertex shaders, and by
// cloth_inspect.frag.glsl for flat shading's face normal, front side only): for
// the normal n and -n, the diffuse term n.l and the Blinn-Phong specular term, seen along toEye.
// Only these four numbers are interpolated across a triangle; fragment_lighting.glsl turns the side it
// sees into a colour with the light's colours. Interpolating the colours instead (two vec3 a side)
// made llvmpipe set up 12 floats per vertex instead of 4 for every triangle (with the single texture
// fetch of fabric_color.glsl and the single pow below, a 256 x 256 cloth drew in 33 ms instead of 46).
uniform vec3 uCameraPos;
uniform vec3 uLightDir;   // unit, towards the light
uniform float uShininess;

// xy: the front (n), zw: the back (-n). The half vector is the same for both sides and only the side
// facing the light has a diffuse or specular term, so one pow serves both.
vec4 lightTwoSided(vec3 n, vec3 toEye) {
    float ndl = dot(n, uLightDir);
    float ndh = dot(n, normalize(uLightDir + toEye));
    float s = pow(max(ndl > 0.0 ? ndh : -ndh, 0.0), uShininess);
    return vec4(max(ndl, 0.0), ndl > 0.0 ? s : 0.0, max(-ndl, 0.0), ndl < 0.0 ? s : 0.0);
}
