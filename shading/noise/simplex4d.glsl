// 4D simplex noise, for the animation section of Gustavson's chapter (1.6: "Perlin noise is
// available in a 4D version ... 3D spatial coordinates and time together provide the texture
// coordinates for an animated solid texture"). The chapter prints no 4D code; this one is ours, in
// the style of simplex3d.glsl: skew F4 = (sqrt 5 - 1)/4, unskew G4 = (5 - sqrt 5)/20, the corners'
// order from each component's rank among the four (six pairwise step()s, each pair once, so that
// ties stay consistent), the mod-289 permutation polynomial (34x + 1)x, gradients on the 32 edge
// midpoints of the 4-cube (one component 0, three +-1), falloff (0.6 - |x|^2)^4, scale 27
// (measured: [-0.98, 0.98] over a 40-unit window).
vec4 mod289(vec4 x) { return x - floor(x * (1.0 / 289.0)) * 289.0; }
float mod289(float x) { return x - floor(x * (1.0 / 289.0)) * 289.0; }
vec4 permute(vec4 x) { return mod289(((x*34.0)+1.0)*x); }
float permute(float x) { return mod289(((x*34.0)+1.0)*x); }

// Edge midpoint k mod 32 of the 4-cube: component floor(k/8) is 0, the others take the signs of
// the three low bits.
vec4 grad4(float hash) {
    float k = mod(hash, 32.0);
    float zero = floor(k / 8.0);
    float b = mod(k, 8.0);
    vec3 s = vec3(mod(b, 2.0), mod(floor(b / 2.0), 2.0), floor(b / 4.0)) * 2.0 - 1.0;
    return vec4(zero == 0.0 ? 0.0 : s.x,
                zero == 1.0 ? 0.0 : (zero < 1.0 ? s.x : s.y),
                zero == 2.0 ? 0.0 : (zero < 2.0 ? s.y : s.z),
                zero == 3.0 ? 0.0 : s.z);
}

float snoise4(vec4 v) {
    const float F4 = 0.309016994374947;  // (sqrt(5) - 1) / 4
    const float G4 = 0.138196601125011;  // (5 - sqrt(5)) / 20
    vec4 i = floor(v + dot(v, vec4(F4)));
    vec4 x0 = v - i + dot(i, vec4(G4));
    // rank of each component among the four (3 = largest); each pair compared once
    vec4 rank = vec4(0.0);
    float c;
    c = step(x0.y, x0.x); rank.x += c; rank.y += 1.0 - c;
    c = step(x0.z, x0.x); rank.x += c; rank.z += 1.0 - c;
    c = step(x0.w, x0.x); rank.x += c; rank.w += 1.0 - c;
    c = step(x0.z, x0.y); rank.y += c; rank.z += 1.0 - c;
    c = step(x0.w, x0.y); rank.y += c; rank.w += 1.0 - c;
    c = step(x0.w, x0.z); rank.z += c; rank.w += 1.0 - c;
    // the simplex walks from corner 0 along the largest component first
    vec4 i1 = step(2.5, rank);
    vec4 i2 = step(1.5, rank);
    vec4 i3 = step(0.5, rank);
    vec4 x1 = x0 - i1 + G4;
    vec4 x2 = x0 - i2 + 2.0 * G4;
    vec4 x3 = x0 - i3 + 3.0 * G4;
    vec4 x4 = x0 - 1.0 + 4.0 * G4;
    i = mod289(i);
    vec4 h = permute(permute(permute(permute(
                 i.w + vec4(0.0, i1.w, i2.w, i3.w))
               + i.z + vec4(0.0, i1.z, i2.z, i3.z))
               + i.y + vec4(0.0, i1.y, i2.y, i3.y))
               + i.x + vec4(0.0, i1.x, i2.x, i3.x));
    float h4 = permute(permute(permute(permute(i.w + 1.0) + i.z + 1.0) + i.y + 1.0) + i.x + 1.0);
    vec4 m = max(0.6 - vec4(dot(x0, x0), dot(x1, x1), dot(x2, x2), dot(x3, x3)), 0.0);
    float m4 = max(0.6 - dot(x4, x4), 0.0);
    m = m * m;
    m4 = m4 * m4;
    vec4 gx = vec4(dot(grad4(h.x), x0), dot(grad4(h.y), x1), dot(grad4(h.z), x2), dot(grad4(h.w), x3));
    return 27.0 * (dot(m * m, gx) + m4 * m4 * dot(grad4(h4), x4));
}
