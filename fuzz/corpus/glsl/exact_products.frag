#version 130
// Multiply-adds whose products are exact for every input (rounded once in the translation) beside
// ones that are not: the permutations of the noises on whole numbers from a bounded floor, a
// chain of them through a function, mod() and a loop counter; products of floors of anything, of
// a varying, and of whole numbers that reach past 2^24, where one rounding and two differ; the
// derivative of a product subtracted.
varying vec2 st;

vec4 mod289(vec4 x) { return x - floor(x * (1.0 / 289.0)) * 289.0; }
vec3 mod289(vec3 x) { return x - floor(x * (1.0 / 289.0)) * 289.0; }
vec4 permute(vec4 x) { return mod289(((x * 34.0) + 1.0) * x); }
float permute(float x) { return mod((34.0 * x + 1.0) * x, 289.0); }

void main() {
    vec3 i = mod289(floor(fract(vec3(st, st.x + st.y)) * 1000.0));
    vec4 p = permute(permute(permute(i.z + vec4(0.0, 1.0, 0.0, 1.0)) + i.y + vec4(0.0, 0.0, 1.0, 1.0))
                     + i.x + vec4(0.0, 1.0, 1.0, 0.0));
    vec2 cell = mod(floor(fract(st) * 600.0), 289.0);
    float hash = 0.0;
    for (int k = -1; k <= 1; k++) {
        hash += permute(permute(cell.x + float(k)) + cell.y);
    }
    float odd = floor(st.x * 1e6) * floor(st.y * 1e6) + 1.0;
    float line = st.x * 34.0 + 1.0;
    float w = floor(fract(st.x) * 64.0) + 5592400.0;
    float past = w * 3.0 + 1.0;  // 3 w is odd and above 2^24 for odd w above 5592405: it rounds
    // a derivative's zero keeps its sign: -0 - (-0 + +0) is -0, where -0 + (+0 + -0) would be +0
    float sign_of_zero = 1.0 / dFdx(-floor(fract(st.x) * 4.0) - (floor(st.y * 4.0) - 8.0) * 2.0);
    gl_FragColor = vec4(p.x / 289.0 + fract(odd * line), hash / 867.0, (past - 16777000.0) / 512.0,
                        sign_of_zero < 0.0 ? 0.25 : 0.75);
}
