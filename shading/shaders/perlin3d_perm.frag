// Noise is Beautiful (notes), "Perlin Noise", "Generating Noise (3D)": "This algorithm can be
// extended to 3D ... Now, we have 8 gradients and vectors, and need to perform 6 interpolations."
// Prose only: the 2D sample code (perlin2d_perm.frag) extended to 3D with the notes' own 3D
// gradient (their scattering example, noise/permute_polynomial.glsl), the quintic fade and the 2D
// code's (1 - u) a + u b along x, then y, then z. A solid texture: P = 4 object units per cell.
varying vec3 P;
vec3 fade(vec3 t) { return ((6.0*t-15.0)*t+10.0)*t*t*t; }
float noise(vec3 p) {
    vec3 f = fract(p);
    vec3 pf = floor(p);
    float n000 = dot(f,                    gradient(pf));
    float n100 = dot(f - vec3(1., 0., 0.), gradient(pf + vec3(1,0,0)));
    float n010 = dot(f - vec3(0., 1., 0.), gradient(pf + vec3(0,1,0)));
    float n110 = dot(f - vec3(1., 1., 0.), gradient(pf + vec3(1,1,0)));
    float n001 = dot(f - vec3(0., 0., 1.), gradient(pf + vec3(0,0,1)));
    float n101 = dot(f - vec3(1., 0., 1.), gradient(pf + vec3(1,0,1)));
    float n011 = dot(f - vec3(0., 1., 1.), gradient(pf + vec3(0,1,1)));
    float n111 = dot(f - vec3(1., 1., 1.), gradient(pf + vec3(1,1,1)));
    vec3 faded = fade(f);
    float n00 = (1. - faded.x) * n000 + faded.x * n100;
    float n10 = (1. - faded.x) * n010 + faded.x * n110;
    float n01 = (1. - faded.x) * n001 + faded.x * n101;
    float n11 = (1. - faded.x) * n011 + faded.x * n111;
    float n0 = (1. - faded.y) * n00 + faded.y * n10;
    float n1 = (1. - faded.y) * n01 + faded.y * n11;
    float n = (1. - faded.z) * n0 + faded.z * n1;
    return (n + 1.) / 2.;
}
void main(void) {
    gl_FragColor = vec4(vec3(noise(P)), 1.0);
}
