// Table 1.1 "Dots" (Figure 1.2): spots from a thresholded distance, a fixed smoothstep width.
varying vec2 st;
void main(void) {
    float grey = smoothstep(0.3, 0.32, length(fract(5.0 * st) - 0.5));
    gl_FragColor = vec4(vec3(grey), 1.0);
}
