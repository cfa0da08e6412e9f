// The colour of a lit fragment from the terms vertex_lighting.glsl interpolated (included by the cloth
// and fringe fragment shaders): ambient + diffuse times the surface colour, plus the specular term in the
// light's colour, for the side the fragment shows.
uniform vec3 uLightColor;
uniform vec3 uAmbient;
uniform float uSpecular;

vec3 shadeLit(vec3 base, vec2 terms) { return base * (uAmbient + uLightColor * terms.x) + uLightColor * (uSpecular * terms.y); }

vec3 shadeTwoSided(vec3 base, vec4 light) { return shadeLit(base, gl_FrontFacing ? light.xy : light.zw); }
