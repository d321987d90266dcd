// Probe of discard: fragments on a pattern of run-time values discard, before a value is
// computed and inside a loop; the others write derivatives taken after the discards, for which
// the discarded fragments of their quads keep running as helpers.
void main(void) {
    vec2 p = gl_FragCoord.xy;
    float v = p.x * p.x + 3.0 * p.y * p.y + p.x * p.y;
    if (mod(p.x + 2.0 * p.y, 5.0) < 1.0) discard;
    float w = v * 0.5 + p.x;
    float acc = 0.0;
    for (int i = 0; i < 8; i++) {
        acc += p.x * float(i + 1);
        if (acc > p.y * 9.0 && mod(p.x, 3.0) < 1.0) discard;
    }
    gl_FragColor = vec4(dFdx(w), dFdy(w), dFdx(acc), dFdy(acc));
}
