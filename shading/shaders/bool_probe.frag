// Probe of bools and bvecs on run-time values (GLSL 1.30): && || ^^ ! == != of bools, the
// component-wise comparisons into bvecs, any, all, not, == of whole vectors, mix with a bvec.
void main(void) {
    vec2 p = gl_FragCoord.xy;
    bool a = p.x < 9.0, b = mod(p.y, 3.0) < 1.5, c = p.x + p.y > 15.0;
    bvec3 v = bvec3(a, b ^^ c, !a || b);
    bvec3 w = lessThan(vec3(p, p.x - p.y), vec3(8.0, 5.0, 0.0));
    bvec2 g = greaterThanEqual(p, vec2(4.0, 6.0));
    float red = float(any(v)) + 2.0 * float(all(w)) + 4.0 * float(v == w) + 8.0 * float(any(not(equal(v, w))));
    float green = float(a && b) + 2.0 * float(a ^^ b) + 4.0 * float(!(a || c)) + 8.0 * float(a != c) +
                  16.0 * float(all(g)) + 32.0 * float(lessThanEqual(p, vec2(5.0)) == notEqual(p, p));
    vec3 m = mix(vec3(1.0, 2.0, 3.0), vec3(-1.0, -2.0, -3.0), w);
    gl_FragColor = vec4(red, green, m.x + 10.0 * m.y + 100.0 * m.z, float(greaterThan(p, vec2(3.0)) != bvec2(b, c)));
}
