// 2D simplex noise with rotating gradients and its analytic gradient ("flow noise",
// Perlin and Neyret 2001), 2011 textureless formulation. Written from the algorithm's statement.
vec3 permute(vec3 x) { return mod(((x*34.0)+1.0)*x, 289.0); }

float srdnoise(vec2 P, float rot, out vec2 grad) {
    const float F2 = 0.366025403;
    const float G2 = 0.211324865;
    const float K = 0.0243902439; // 1/41
    // Skew to the simplex grid and find the first corner
    vec2 Pi = floor(P + dot(P, vec2(F2)));
    vec2 v0 = P - (Pi - dot(Pi, vec2(G2)));
    // The other two corners
    vec2 i1 = (v0.x > v0.y) ? vec2(1.0, 0.0) : vec2(0.0, 1.0);
    vec2 v1 = v0 - i1 + G2;
    vec2 v2 = v0 - 1.0 + 2.0 * G2;
    Pi = mod(Pi, 289.0);
    // Hash of the three corners, then a rotated gradient on a diamond
    vec3 x = Pi.x + vec3(0.0, i1.x, 1.0);
    vec3 y = Pi.y + vec3(0.0, i1.y, 1.0);
    vec3 u = permute(permute(x) + y) * K + rot;
    u = 4.0 * fract(u) - 2.0;
    vec3 gx = abs(u) - 1.0;
    vec3 gy = abs(abs(u + 1.0) - 2.0) - 1.0;
    // Radial kernels
    vec3 t = max(0.5 - vec3(dot(v0, v0), dot(v1, v1), dot(v2, v2)), 0.0);
    vec3 t2 = t * t;
    vec3 t4 = t2 * t2;
    vec3 gv = vec3(gx.x * v0.x + gy.x * v0.y, gx.y * v1.x + gy.y * v1.y, gx.z * v2.x + gy.z * v2.y);
    float n = 40.0 * dot(t4, gv);
    // d/dv [t^4 (g.v)] = t^4 g - 8 t^3 (g.v) v, since dt/dv = -2 v
    vec3 t3gv = t2 * t * gv;
    grad.x = dot(t4, gx) - 8.0 * dot(t3gv, vec3(v0.x, v1.x, v2.x));
    grad.y = dot(t4, gy) - 8.0 * dot(t3gv, vec3(v0.y, v1.y, v2.y));
    grad *= 40.0;
    return n;
}
