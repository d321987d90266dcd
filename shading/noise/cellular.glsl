// Cellular (Worley) noise, the 2011 textureless variants used by the chapter. One feature point
// per unit cell, hashed with the permutation polynomial; written from the algorithm's statement.
// F1 and F2 are the smallest and second-smallest distances: a running insertion keeps both.
vec4 permute(vec4 x) { return mod((34.0 * x + 1.0) * x, 289.0); }
vec3 permute(vec3 x) { return mod((34.0 * x + 1.0) * x, 289.0); }
float permute(float x) { return mod((34.0 * x + 1.0) * x, 289.0); }

const float K = 0.142857142857;   // 1/7
const float Ko = 0.428571428571;  // 3/7
const float K2 = 0.020408163265306; // 1/49
const float Kz = 0.166666666667;  // 1/6
const float Kzo = 0.416666666667; // 1/2-1/6*2

// Keep the two smallest of the squared distances seen so far (and the vectors to them).
void insert(float d, vec2 v, inout vec2 F, inout vec4 d1d2) {
    bool first = d < F.x;
    bool second = d < F.y;
    d1d2.zw = first ? d1d2.xy : (second ? v : d1d2.zw);
    d1d2.xy = first ? v : d1d2.xy;
    F = vec2(min(F.x, d), min(F.y, max(F.x, d)));
}

// 2D, 3x3 search, jitter 1.0: F1, F2 and the vectors to the two nearest points.
vec2 cellular_vectors(vec2 P, out vec4 d1d2) {
    const float jitter = 1.0;
    vec2 Pi = mod(floor(P), 289.0);
    vec2 Pf = fract(P);
    vec2 F = vec2(1e6);
    d1d2 = vec4(0.0);
    for (int i = -1; i <= 1; i++) {
        for (int j = -1; j <= 1; j++) {
            float p = permute(permute(Pi.x + float(i)) + Pi.y + float(j));
            float ox = fract(p * K) - Ko;
            float oy = mod(floor(p * K), 7.0) * K - Ko;
            vec2 d = vec2(Pf.x - (float(i) + 0.5) + jitter * ox, Pf.y - (float(j) + 0.5) + jitter * oy);
            insert(dot(d, d), d, F, d1d2);
        }
    }
    return sqrt(F);
}
vec2 cellular(vec2 P) { vec4 d1d2; return cellular_vectors(P, d1d2); }

// 3D, 2x2x2 search, jitter 0.8, F1 only (returned in both components).
vec2 cellular2x2x2(vec3 P) {
    const float jitter = 0.8;
    vec3 Pi = mod(floor(P), 289.0);
    vec3 Pf = fract(P);
    float F1 = 1e6;
    for (int a = 0; a <= 1; a++) {
        for (int b = 0; b <= 1; b++) {
            for (int c = 0; c <= 1; c++) {
                float p = permute(permute(permute(Pi.x + float(a)) + Pi.y + float(b)) + Pi.z + float(c));
                vec3 o = vec3(fract(p * K) - Ko, mod(floor(p * K), 7.0) * K - Ko, floor(p * K2) * Kz - Kzo);
                vec3 d = Pf - vec3(float(a), float(b), float(c)) + jitter * o;
                F1 = min(F1, dot(d, d));
            }
        }
    }
    return vec2(sqrt(F1));
}

// 3D, 3x3x3 search, jitter 1.0: F1 and F2.
vec2 cellular(vec3 P) {
    const float jitter = 1.0;
    vec3 Pi = mod(floor(P), 289.0);
    vec3 Pf = fract(P) - 0.5;
    vec2 F = vec2(1e6);
    vec4 unused = vec4(0.0);
    for (int a = -1; a <= 1; a++) {
        for (int b = -1; b <= 1; b++) {
            for (int c = -1; c <= 1; c++) {
                float p = permute(permute(permute(Pi.x + float(a)) + Pi.y + float(b)) + Pi.z + float(c));
                vec3 o = vec3(fract(p * K) - Ko, mod(floor(p * K), 7.0) * K - Ko, floor(p * K2) * Kz - Kzo);
                vec3 d = Pf - vec3(float(a), float(b), float(c)) + jitter * o;
                float d2 = dot(d, d);
                F = vec2(min(F.x, d2), min(F.y, max(F.x, d2)));
            }
        }
    }
    return sqrt(F);
}
