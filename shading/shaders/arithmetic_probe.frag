// Probe of how the driver divides: a quotient of two run-time values, mod by a constant and by
// a run-time value, to a float target (compared bit for bit).
void main(void) {
    float a = gl_FragCoord.x * 7.13 + gl_FragCoord.y * 289.0;
    float b = gl_FragCoord.y * 0.37 + 1.0;
    gl_FragColor = vec4(a / b, mod(a, 289.0), mod(a, b), a / 7.0);
}
