// Noise is Beautiful (notes), "Perlin Noise: Sample Code": the permutation
// polynomial with two parameters for the gradients and the quintic fade, unchanged (`7.f` is
// GLSL 1.20); main() is ours (the notes: "Try running this in ShaderToy!"): noise(st * 10).
varying vec2 st;
// permute(x, b): noise/permute_polynomial.glsl, the notes', shared with its other listings.
vec2 gradient(vec2 p) {
    // Adjustable pseudo-random generator parameter
    float B1 = 7.f;
    float B2 = 23.f;
    float x = permute(permute(p.x, B1) + p.y, B1) / 288.f;
    float y = permute(permute(p.x, B2) + p.y, B2) / 288.f;
    // Our permutation function gives us a value in [0,1].
    // Convert this to a gradient vector that can go in any direction.
    return normalize(vec2(x,y) - vec2(0.5, 0.5));
}
// Perlin Noise
vec2 fade(vec2 t) { return ((6.0*t-15.0)*t+10.0)*t*t*t; }
float noise(vec2 p) {
    float s = fract(p.x);
    float t = fract(p.y);
    vec2 v00 = vec2(s,t);
    vec2 v01 = vec2(s,t - 1.);
    vec2 v10 = vec2(s - 1.,t);
    vec2 v11 = vec2(s - 1.,t - 1.);
    vec2 pf = floor(p);
    vec2 g00 = gradient(pf);
    vec2 g01 = gradient(pf + vec2(0,1));
    vec2 g10 = gradient(pf + vec2(1,0));
    vec2 g11 = gradient(pf + vec2(1,1));
    float n00 = dot(v00, g00);
    float n01 = dot(v01, g01);
    float n10 = dot(v10, g10);
    float n11 = dot(v11, g11);
    vec2 faded = fade(vec2(s,t));
    float n0 = (1. - faded.x) * n00 + faded.x * n10;
    float n1 = (1. - faded.x) * n01 + faded.x * n11;
    float n = (1. - faded.y) * n0 + faded.y * n1;
    return (n + 1.) / 2.;
}
void main(void) {
    gl_FragColor = vec4(vec3(noise(st * 10.0)), 1.0);
}
