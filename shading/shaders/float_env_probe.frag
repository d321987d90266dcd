// Probe of the float environment on run-time values: per column, one edge case GLSL leaves
// undefined or that depends on denormal handling. z is 0 at run time (the compiler cannot fold it).
//   x in [0, 1): normalize(vec3(0)).x     [1, 2): inversesqrt(0)     [2, 3): pow(-2, 1.5)
//   [3, 4): mod(1, 0)                     [4, 5): 1e-41 (a denormal) * 1e30
//   [5, 6): sqrt(-1)                      [6, 7): log(0)             [7, 8): 0 * inversesqrt(0)
void main(void) {
    float z = floor(gl_FragCoord.x / 4096.0);
    float column = floor(gl_FragCoord.x);
    float v;
    if (column < 1.0) v = normalize(vec3(z)).x;
    else if (column < 2.0) v = inversesqrt(z);
    else if (column < 3.0) v = pow(-2.0 + z, 1.5);
    else if (column < 4.0) v = mod(1.0 + z, z);
    else if (column < 5.0) v = ((1e-38 + z) * 1e-3) * 1e30;
    else if (column < 6.0) v = sqrt(-1.0 + z);
    else if (column < 7.0) v = log(z);
    else v = z * inversesqrt(z);
    gl_FragColor = vec4(v, 0.0, 0.0, 1.0);
}
