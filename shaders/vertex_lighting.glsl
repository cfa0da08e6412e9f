// Gouraud lighting of one vertex (included by cloth.vert.glsl and fringe.vert.glsl): ambient + diffuse
// + Blinn-Phong specular for the normal n, seen along toEye.
uniform vec3 uCameraPos;
uniform vec3 uLightDir;   // unit, towards the light
uniform vec3 uLightColor;
uniform vec3 uAmbient;
uniform float uSpecular;
uniform float uShininess;

void lightVertex(vec3 n, vec3 toEye, out vec3 diffuse, out vec3 specular) {
    float ndl = max(dot(n, uLightDir), 0.0);
    vec3 h = normalize(uLightDir + toEye);
    float s = ndl > 0.0 ? pow(max(dot(n, h), 0.0), uShininess) : 0.0;
    diffuse = uAmbient + uLightColor * ndl;
    specular = uLightColor * (uSpecular * s);
}
