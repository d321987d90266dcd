// Noise is Beautiful (notes), "Simplex Noise: Sample Code": the gradient (B1 = 7,
// B2 = 6), the xy_to_uv shear and noise(), unchanged (the prose says 0.8 for the falloff under
// the stretched grid, the code 0.75: the code is kept). Needs permute_polynomial.glsl first.
// dnoise() is ours: the notes name it in their warping code ("Warping") and states the sum in a
// formula that was an image. It is d/dp of noise(p), corner by corner: with t = 0.75 - v.v and
// w = t^4 (where t > 0), d/dp [w (g.v)] = t^4 g - 8 t^3 (g.v) v, since dv/dp is the identity;
// times the output's scale 10.9 / 2.
vec2 gradient(vec2 p) {
    float B1 = 7.f;
    float B2 = 6.f;
    float x = permute(permute(p.x, B1) + p.y, B1) / 288.f;
    float y = permute(permute(p.x, B2) + p.y, B2) / 288.f;
    // Our permutation function gives us a value in [0,1].
    // Convert this to a gradient vector that can go in any direction.
    return normalize(vec2(x,y) - vec2(0.5, 0.5));
}
// Perlin Noise:
vec2 xy_to_uv(vec2 xy) { return vec2(xy.x + xy.y * 0.5, xy.y); }
vec2 uv_to_xy(vec2 uv) { return vec2(uv.x - uv.y * 0.5, uv.y); }
float noise(vec2 p) {
    vec2 uv = xy_to_uv(p);
    // Find the corners of my simplex
    vec2 uv0 = floor(uv);
    vec2 luv = fract(uv); // Local
    vec2 uv1 = uv0;
    uv1 += vec2(step(luv.y, luv.x), step(luv.x, luv.y));
    vec2 uv2 = uv0 + vec2(1., 1.);
    // Sample my gradient function
    vec2 g0 = gradient(uv0);
    vec2 g1 = gradient(uv1);
    vec2 g2 = gradient(uv2);
    // Compute my noise contributions
    vec2 v0 = p - uv_to_xy(uv0);
    float w0 = max(0.75 - dot(v0, v0), 0.);
    w0 = w0 * w0;
    w0 = w0 * w0;
    vec2 v1 = p - uv_to_xy(uv1);
    float w1 = max(0.75 - dot(v1, v1), 0.);
    w1 = w1 * w1;
    w1 = w1 * w1;
    vec2 v2 = p - uv_to_xy(uv2);
    float w2 = max(0.75 - dot(v2, v2), 0.);
    w2 = w2 * w2;
    w2 = w2 * w2;
    float n0 = w0 * dot(g0, v0);
    float n1 = w1 * dot(g1, v1);
    float n2 = w2 * dot(g2, v2);
    float n = n0 + n1 + n2;
    // Scale to [0,1]
    return (10.9 * n + 1.) / 2.;
}
// One corner's term of dnoise: d/dp [max(0.75 - v.v, 0)^4 (g.v)].
vec2 dcorner(vec2 g, vec2 v) {
    float t = max(0.75 - dot(v, v), 0.);
    float t3 = t * t * t;
    return t3 * (t * g - 8. * dot(g, v) * v);
}
vec2 dnoise(vec2 p) {
    // noise()'s simplex and gradients
    vec2 uv = xy_to_uv(p);
    vec2 uv0 = floor(uv);
    vec2 luv = fract(uv);
    vec2 uv1 = uv0;
    uv1 += vec2(step(luv.y, luv.x), step(luv.x, luv.y));
    vec2 uv2 = uv0 + vec2(1., 1.);
    vec2 d = dcorner(gradient(uv0), p - uv_to_xy(uv0))
           + dcorner(gradient(uv1), p - uv_to_xy(uv1))
           + dcorner(gradient(uv2), p - uv_to_xy(uv2));
    return 10.9 / 2. * d;
}
