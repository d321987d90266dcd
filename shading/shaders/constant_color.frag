// Table 1.1 "Constant color".
void main(void) {
    gl_FragColor = vec4(1.0, 0.5, 0.0, 1.0);
}
