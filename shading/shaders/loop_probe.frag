// Probe of loops whose exits depend on the fragment: break (Collatz steps from a number per
// pixel), continue, return from inside a loop, and a while loop on a varying condition around
// a loop that breaks; each fragment's values as it left. The arithmetic is exact (integers and
// multiples of 1/64), so Mesa's freedom to reassociate cannot change a result.
float first_step(float start, float step) {
    float v = start;
    for (int i = 0; i < 20; i++) {
        v += step;
        if (fract(v * 0.375) > 0.8) return v;
    }
    return -1.0;
}

void main(void) {
    vec2 p = floor(gl_FragCoord.xy);
    float v = p.x + 64.0 * p.y + 1.0, steps = 0.0, peak = v;
    for (int i = 0; i < 200; i++) {
        if (v == 1.0) break;
        if (mod(v, 2.0) == 0.0) v = v * 0.5;
        else v = 3.0 * v + 1.0;
        peak = max(peak, v);
        steps += 1.0;
    }
    float sum = 0.0;
    for (int i = 0; i < 12; i++) {
        if (mod(float(i) + p.x, 3.0) < 1.0) continue;
        sum += float(i) * 0.5;
    }
    float t = 0.0, k = 0.0;
    while (t < gl_FragCoord.y * 0.25) {
        for (int j = 0; j < 4; j++) {
            t += 0.75;
            if (t > gl_FragCoord.x * 0.5) break;
        }
        k += 1.0;
        if (k > 6.0) break;
    }
    gl_FragColor = vec4(steps, peak, sum + 64.0 * (t + 100.0 * k), first_step((p.x - 31.0) * 0.0625, 0.125));
}
