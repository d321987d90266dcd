#version 130
// Loop nests whose heads read only the counters and values declared before them: the writer runs
// those for all iterations at once where the values are alike in every lane. A cellular search
// over a 3x3 neighbourhood, its cells a few pixels wide (batches in one cell and across two); a
// Voronoi search; the same over 3x3x3 cells (27 iterations: more than a batch of 16 lanes holds)
// inside an octave loop whose counter the head reads; an int cell; a head under a condition that
// varies per fragment; lanes whose value differs only in the sign of zero; and nests the writer
// leaves as they are: a head reading a varying, or one too short to pay.
varying vec2 st;

float permute(float x) { return mod((34.0 * x + 1.0) * x, 289.0); }

// The two nearest feature points' squared distances.
vec2 search(vec2 P) {
    vec2 Pi = mod(floor(P), 289.0);
    vec2 Pf = fract(P);
    vec2 F = vec2(1e6);
    for (int i = -1; i <= 1; i++) {
        for (int j = -1; j <= 1; j++) {
            float p = permute(permute(Pi.x + float(i)) + Pi.y + float(j));
            vec2 o = vec2(fract(p / 7.0), mod(floor(p / 7.0), 7.0) / 7.0);
            vec2 d = Pf - vec2(float(i), float(j)) - o;
            float dd = dot(d, d);
            F = vec2(min(F.x, dd), min(F.y, max(F.x, dd)));
        }
    }
    return F;
}

// A Voronoi search as shaders on the web write it: the neighbour's offset first, which reads no
// per-lane value, then its hash of the cell; the outer loop's body the inner loop, unbraced.
float voronoi(vec2 x) {
    vec2 n = floor(x);
    vec2 f = fract(x);
    float md = 8.0;
    for (int j = -1; j <= 1; j++)
        for (int i = -1; i <= 1; i++) {
            vec2 g = vec2(float(i), float(j));
            vec2 o = fract(sin(vec2(dot(n + g, vec2(127.1, 311.7)), dot(n + g, vec2(269.5, 183.3)))) * 43758.5453);
            vec2 r = g + o - f;
            md = min(md, dot(r, r));
        }
    return md;
}

float search3(vec3 P) {
    float nearest = 1e6;
    for (int octave = 0; octave < 2; octave++) {
        vec3 Pi = mod(floor(P * float(octave + 1)), 289.0);
        vec3 Pf = fract(P * float(octave + 1));
        for (int a = -1; a <= 1; a++) {
            for (int b = -1; b <= 1; b++) {
                for (int c = -1; c <= 1; c++) {
                    vec3 o = vec3(permute(Pi.x + float(a)), permute(Pi.y + float(b) + float(octave)),
                                  permute(Pi.z + float(c))) / 289.0;
                    vec3 d = Pf - vec3(float(a), float(b), float(c)) - o;
                    nearest = min(nearest, dot(d, d));
                }
            }
        }
    }
    return nearest;
}

void main() {
    vec2 F = search(st * 5.0);
    float g = search3(vec3(st * 3.0, 0.5)) + voronoi(st * 6.0);

    ivec2 cell = ivec2(floor(st * 6.0));
    float h = 0.0;
    for (int k = 0; k < 4; k++) {
        float hk = permute(permute(float(cell.x * 3 + k)) + float(cell.y)) / 289.0;
        h += hk;
    }

    float s = 0.0;
    if (st.x > 0.4) {
        vec2 c = floor(st * 4.0);
        for (int i = 0; i < 3; i++) {
            float w = sin(c.x * 1.7 + float(i)) * cos(c.y * 2.3 - float(i)) + c.x * c.y;
            s += fract(w);
        }
    }

    // -0.0 left of a line through a block, +0.0 right of it: 1 / (q * n) is -inf or +inf.
    float q = st.x < 0.47 ? -floor(fract(st.y)) : floor(fract(st.y));
    float z = 0.0;
    for (int i = 1; i <= 2; i++) {
        float r = 1.0 / (q * float(i)) + sin(float(i)) * cos(float(i)) - tan(float(i));
        z += clamp(r, -1.0, 1.0);
    }

    // Reads the varying: every fragment its own.
    float v = 0.0;
    for (int i = 0; i < 3; i++) {
        float vi = permute(permute(floor(st.x * 40.0) + float(i)));
        v += vi / 289.0;
    }

    // Two operations: left as written.
    float t = 0.0;
    for (int i = 0; i < 3; i++) {
        float ti = F.x + float(i);
        t += ti;
    }

    gl_FragColor = vec4(F.x + 0.1 * g, F.y + 0.05 * h, 0.2 * s + 0.1 * z, 0.01 * (v + t));
}
