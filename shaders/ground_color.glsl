// The ground's colour at a world point (included by ground.frag.glsl and shadow.frag.glsl): 1 m
// checker tiles lit from above, darkened by `darkness` (0: none), fading into the sky with distance.
uniform vec3 uColor;
uniform vec3 uSky;
uniform vec3 uCameraPos;
uniform vec3 uLightDir;
uniform vec3 uLightColor;
uniform vec3 uAmbient;
uniform float uFadeDistance;

vec3 groundColor(vec3 world, float darkness) {
    vec2 cell = floor(world.xz);
    float checker = 1.0 - 0.14 * mod(cell.x + cell.y, 2.0);
    vec3 lit = uColor * checker * (uAmbient + uLightColor * max(uLightDir.y, 0.0)) * (1.0 - darkness);
    vec3 d = world - uCameraPos;
    float fade = clamp(dot(d, d) / (uFadeDistance * uFadeDistance), 0.0, 1.0);
    return mix(lit, uSky, fade);
}
