// Noise is Beautiful (notes), "Generating Noise (3D)" of "Simplex Noise": 3D simplex noise
// ("Transform the point to skewed space ... Find the 4 closest corners ... This can be done with
// step functions! ... To generate gradients in 3D, we can use a Fibonacci Sphere"). The notes print
// no code and their formulas were images: written here from that prose, in the notes' style.
// Perlin's skew to the simplex grid (F3 = 1/3, unskew G3 = 1/6), the corners by step functions,
// radial falloff (0.6 - |v|^2)^4, each corner hashed by the notes' permute (b = 10), its gradient
// point h of 289 on a Fibonacci sphere. Needs permute_polynomial.glsl first.
vec3 fibonacci_sphere(float i) {
    // Point i of 289 on a Fibonacci sphere. The azimuth is taken as a fraction of a turn first so
    // that sin and cos see arguments in [0, 2 pi), not up to 289 * 2.4.
    float z = 1.0 - (2.0 * i + 1.0) / 289.0;
    float r = sqrt(1.0 - z * z);
    float phi = 6.28318531 * fract(i * 0.618033989);
    return vec3(r * cos(phi), r * sin(phi), z);
}
vec3 corner_gradient(vec3 c) {
    return fibonacci_sphere(permute(permute(permute(c.x, 10.0) + c.y, 10.0) + c.z, 10.0));
}
// The noise in [0,1] (the notes' convention; measured [0.117, 0.888] over
// 60x60 cells); grad
// receives its gradient in p, d/dp [t^4 (g.v)] = t^4 g - 8 t^3 (g.v) v for each corner.
float noise3(vec3 p, out vec3 grad) {
    const float F3 = 1.0 / 3.0;
    const float G3 = 1.0 / 6.0;
    vec3 c0 = floor(p + dot(p, vec3(F3)));
    vec3 v0 = p - c0 + dot(c0, vec3(G3));
    vec3 g = step(v0.yzx, v0.xyz);
    vec3 l = 1.0 - g;
    vec3 i1 = min(g.xyz, l.zxy);
    vec3 i2 = max(g.xyz, l.zxy);
    vec3 v1 = v0 - i1 + G3;
    vec3 v2 = v0 - i2 + 2.0 * G3;
    vec3 v3 = v0 - 1.0 + 3.0 * G3;
    vec3 g0 = corner_gradient(c0);
    vec3 g1 = corner_gradient(c0 + i1);
    vec3 g2 = corner_gradient(c0 + i2);
    vec3 g3 = corner_gradient(c0 + 1.0);
    vec4 t = max(0.6 - vec4(dot(v0, v0), dot(v1, v1), dot(v2, v2), dot(v3, v3)), 0.0);
    vec4 gv = vec4(dot(g0, v0), dot(g1, v1), dot(g2, v2), dot(g3, v3));
    vec4 t3 = t * t * t;
    vec4 t4 = t3 * t;
    float n = dot(t4, gv);
    grad = t4.x * g0 + t4.y * g1 + t4.z * g2 + t4.w * g3
         - 8.0 * (t3.x * gv.x * v0 + t3.y * gv.y * v1 + t3.z * gv.z * v2 + t3.w * gv.w * v3);
    const float scale = 32.0;  // so that the output fills about [0,1]
    grad *= 0.5 * scale;
    return (scale * n + 1.0) / 2.0;
}
