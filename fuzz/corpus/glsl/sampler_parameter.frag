// Functions taking a sampler: a lookup with the level of detail of the fragment's quad, passed on
// through a second function.
uniform sampler2D teximage;
varying vec2 st;

vec4 shifted(sampler2D tex, vec2 uv, vec2 by) { return texture2D(tex, uv + by); }

vec4 two_scales(sampler2D tex, vec2 uv) { return 0.5 * (shifted(tex, uv, vec2(0.1, 0.0)) + shifted(tex, uv * 3.0, vec2(0.0))); }

void main() {
    gl_FragColor = two_scales(teximage, st);
}
