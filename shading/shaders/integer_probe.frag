// Probe of GLSL integers on run-time values (GLSL 1.30): an int and a uint made from
// gl_FragCoord, one operation per column (x mod 8), the two results' bits written as 16-bit
// halves to the four channels of a float target, exactly. Only cases GLSL defines: divisors are
// not zero, % has no negative operand, shift counts lie in [0, 32), conversions are in range.
void main(void) {
    int x = int(gl_FragCoord.x), y = int(gl_FragCoord.y);
    int a = x * 7919 - y * 104729 + (x << 20) - 3;
    int b = (y % 7 + 1) * (x % 11 + 2);
    uint u = uint(a) * 2654435761u + uint(b) * 40503u;
    uint v = uint(b) + 0x9E3779B9u * uint(y);
    int column = x % 8;
    int r;
    uint s;
    if (column == 0) {
        r = a * b + b * b * b;
        s = u * v + (u ^ v);
    } else if (column == 1) {
        r = a / b + (-a) / (b + 1);
        s = u / (v | 1u) + u / 3u;
    } else if (column == 2) {
        r = (a & 0x7FFFFFFF) % b;
        s = u % (v | 1u);
    } else if (column == 3) {
        r = (a >> (b & 31)) + (a << (y & 15));
        s = (u >> uint(b & 31)) ^ (u << 7u);
    } else if (column == 4) {
        r = (a & b) | (a ^ ~b);
        s = ~u & (v | 0xF0F0F0F0u);
    } else if (column == 5) {
        r = int(float(a) * 0.001) + int(-2.75 * float(b));
        s = uint(abs(float(a)) * 0.5) + uint(float(b) * 1.5);
    } else if (column == 6) {
        r = min(a, b) + max(a, b) * sign(a) + abs(a) + clamp(a, -100, 100);
        s = min(u, v) + max(u, 7u) + clamp(u, 3u, 9u);
    } else {
        ivec2 p = ivec2(a, b) * 3 - ivec2(1, 2);
        uvec3 q = uvec3(u, v, 5u) >> uvec3(1u, 2u, 3u);
        r = p.x ^ p.y;
        s = q.x + q.y * q.z;
    }
    uint rb = uint(r);
    gl_FragColor = vec4(float(rb >> 16u), float(rb & 0xFFFFu), float(s >> 16u), float(s & 0xFFFFu));
}
