// Figure 1.2 dots, anti-aliased with aastep (Listing 1.1) instead of a fixed width.
varying vec2 st;
void main(void) {
    gl_FragColor = vec4(vec3(aastep(0.31, length(fract(5.0 * st) - 0.5))), 1.0);
}
