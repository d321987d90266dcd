// Probe of the integer cases GLSL leaves undefined (GLSL 1.30), one per column, on run-time
// values (z is 0 at run time, so the compiler cannot fold them), both results' bits written as
// 16-bit halves. llvmpipe only: softpipe traps on an integer division by zero.
//   0: 7 / 0, 7u / 0u                    1: 7 % 0, 7u % 0u
//   2: -7 % 3, 7 % -3                    3: INT_MIN / -1, INT_MIN % -1
//   4: 5 << 33, 5u >> 33u                5: -5 >> 32, 5u << 32u
//   6: 5 << -1, 5u >> 0xFFFFFFFFu        7: int(-1.5) (defined), uint(-1.0)
//   8: int(3e9), uint(5e9)               9: int(-3e9), uint(-3e9)
//  10: int(NaN), uint(NaN)              11: int(+inf), uint(+inf)
//  12: int(-inf), uint(-inf)            13: int(2147483520.0), uint(4294967040.0) (defined)
void main(void) {
    int column = int(gl_FragCoord.x);
    int z = int(gl_FragCoord.y);
    uint uz = uint(z);
    float fz = float(z);
    int r = 0;
    uint s = 0u;
    if (column == 0) { r = 7 / z; s = 7u / uz; }
    else if (column == 1) { r = 7 % z; s = 7u % uz; }
    else if (column == 2) { r = (-7 + z) % 3; s = uint((7 + z) % -3); }
    else if (column == 3) { r = (-2147483647 - 1 + z) / (z - 1); s = uint((-2147483647 - 1 + z) % (z - 1)); }
    else if (column == 4) { r = (5 + z) << (33 + z); s = (5u + uz) >> (33u + uz); }
    else if (column == 5) { r = (-5 + z) >> (32 + z); s = (5u + uz) << (32u + uz); }
    else if (column == 6) { r = (5 + z) << (-1 + z); s = (5u + uz) >> uint(-1 + z); }
    else if (column == 7) { r = int(-1.5 + fz); s = uint(-1.0 + fz); }
    else if (column == 8) { r = int(3e9 + fz); s = uint(5e9 + fz); }
    else if (column == 9) { r = int(-3e9 + fz); s = uint(-3e9 + fz); }
    else if (column == 10) { float n = sqrt(-1.0 + fz); r = int(n); s = uint(n); }
    else if (column == 11) { float i = 1.0 / fz; r = int(i); s = uint(i); }
    else if (column == 12) { float i = -1.0 / fz; r = int(i); s = uint(i); }
    else { r = int(2147483520.0 + fz); s = uint(4294967040.0 + fz); }
    uint rb = uint(r);
    gl_FragColor = vec4(float(rb >> 16u), float(rb & 0xFFFFu), float(s >> 16u), float(s & 0xFFFFu));
}
