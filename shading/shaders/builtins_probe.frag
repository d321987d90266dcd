// Probe of built-ins on run-time values (GLSL 3.30), one group per column (x mod 8): rounding,
// angles, reflect, faceforward, refract, isnan, isinf, modf, bits of floats, write swizzles,
// mix with a bool, step, any, all; then asin, acos, tan and atan, which Mesa approximates. The
// inputs are multiples of 1/16 and 1/2, so most results are exact whatever order Mesa picks.
void main(void) {
    vec2 p = floor(gl_FragCoord.xy);
    float z = floor(p.x / 4096.0);  // 0 at run time
    float s = (p.x - 31.0) * 0.0625, t = (p.y - 7.0) * 0.5;
    vec3 I = vec3(s, -1.0, t * 0.25), N = vec3(0.25, 1.0, s * 0.5);
    int column = int(mod(p.x, 8.0));
    vec4 r;
    if (column == 0) {
        r = vec4(round(t), roundEven(s * 8.0 + 0.5), trunc(t), ceil(-t));
    } else if (column == 1) {
        r = vec4(degrees(s), radians(t), sign(s), fract(-t));
    } else if (column == 2) {
        r = vec4(reflect(I, N), dot(faceforward(N, I, vec3(0.0, t, 1.0)), vec3(1.0)));
    } else if (column == 3) {
        r = vec4(refract(I * 0.5, N * 0.5, 0.75 + s * 0.25), float(isnan(z / z)) + 2.0 * float(isinf(s / z)) + 4.0 * float(isnan(s)));
    } else if (column == 4) {
        float i;
        float f = modf(t * 3.0 + s, i);
        r = vec4(f, i, intBitsToFloat(floatBitsToInt(s) ^ int(0x80000000)), uintBitsToFloat(floatBitsToUint(t) + 1u));
    } else if (column == 5) {
        vec4 v = vec4(s, t, s * t, 1.0);
        v.xy -= vec2(t, 2.0);
        v.wz = v.xy * 0.5;
        v.yxw *= vec3(1.5, -1.0, 0.25);
        r = v + vec4(float(floatBitsToUint(s) >> 20u), float(floatBitsToInt(t) & 0xFFFF), 0.0, 0.0);
    } else if (column == 6) {
        r = vec4(mix(s, t, t > 0.0), step(0.0, s) + 2.0 * float(any(lessThan(vec3(s, t, s + t), vec3(0.0)))),
                 float(all(greaterThanEqual(vec2(s, t), vec2(-0.5)))), float(notEqual(vec2(s, t), vec2(s, 0.0)).y));
    } else {
        r = vec4(asin(clamp(s, -1.0, 1.0)), acos(clamp(s * 0.5, -1.0, 1.0)), tan(s), atan(t, s));
    }
    gl_FragColor = r;
}
