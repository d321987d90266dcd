// Probe of matrices on run-time values (GLSL 1.50): column-major constructors, matrix * vector,
// vector * matrix and matrix * matrix of square and non-square shapes, transpose, outerProduct,
// matrixCompMult, determinant and inverse; one result per column (x mod 8). The components are
// multiples of 1/8 in [-2, 2], so every product and sum is exact and only inverse rounds (once,
// in its division): a wrong layout shows, Mesa's freedom to reassociate cannot.
void main(void) {
    vec2 p = floor(gl_FragCoord.xy);
    vec4 q = vec4(mod(p.x, 9.0) * 0.25 - 1.0, mod(p.y, 7.0) * 0.25 - 0.75, mod(p.x + p.y, 5.0) * 0.25 - 0.5,
                  1.5 - mod(p.x * 3.0 + p.y, 11.0) * 0.25);
    mat2 m2 = mat2(q.x, q.y, q.z, q.w + 1.25);
    mat3 m3 = mat3(q.xyz, q.yzw + 0.5, vec3(q.w, 1.0, q.x - q.z));
    mat4 m4 = mat4(q, q.wzyx * 0.5 + 0.25, vec4(1.0, q.x, -q.y, 0.5), vec4(q.zw, 0.25, q.x + 1.0));
    mat2x3 a = mat2x3(q.xyz, q.wxy);
    mat3x2 b = mat3x2(q.xy, q.zw, q.yx);
    mat4x3 c = mat4x3(m4);
    mat3x4 d = transpose(c);
    int column = int(mod(p.x, 8.0));
    vec4 r;
    if (column == 0) r = vec4(m2 * q.xy, q.zw * m2);
    else if (column == 1) r = vec4(m3 * q.xyz, determinant(m3));
    else if (column == 2) r = m4 * q + q * m4;
    else if (column == 3) r = vec4(a * b * q.xyz, determinant(m4));
    else if (column == 4) r = vec4((b * a)[1], (d * c)[2].zw);
    else if (column == 5) r = inverse(m4)[2] + vec4(inverse(m3)[0], inverse(m2)[1][0]);
    else if (column == 6) r = vec4(outerProduct(q.xy, q.zwx)[2], matrixCompMult(m3, mat3(q.w))[1].yz);
    else r = vec4(mat3(m4) * q.xyz, (m2 * transpose(m2))[1][1]);
    gl_FragColor = r;
}
