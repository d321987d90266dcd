// Probe of smoothstep with equal edges (undefined in GLSL; aastep with a zero derivative): the
// edge e is a varying, so the compiler cannot fold it, and every fourth pixel sits exactly on it.
void main(void) {
    float e = floor(gl_FragCoord.x / 4.0) * 4.0 + 2.5;
    gl_FragColor = vec4(smoothstep(e, e, gl_FragCoord.x), step(e, gl_FragCoord.x), 0.0, 1.0);
}
