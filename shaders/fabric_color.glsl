// The cloth's surface colour (included by cloth.frag.glsl and cloth_inspect.frag.glsl): the texture
// (or white) times the front tint; the back is the same fabric, duller and darker (uBackColor a
// shade), as the wrong side of a weave; untextured, the back is uBackColor itself.
uniform sampler2D uTexture;
uniform bool uUseTexture;
uniform vec3 uFrontTint;
uniform vec3 uBackColor;

vec3 fabricColor(vec2 uv) {
    // One texture fetch for both sides: llvmpipe shades a block of fragments at once under a mask and
    // ran both arms of a branch on gl_FrontFacing, so a fetch in each arm cost two.
    vec3 fabric = uUseTexture ? texture(uTexture, uv).rgb : vec3(1.0);
    if (gl_FrontFacing) return fabric * uFrontTint;
    return uUseTexture ? mix(vec3(dot(fabric, vec3(0.3, 0.55, 0.15))), fabric, 0.8) * uBackColor : uBackColor;
}
