// noise_bumps drawn live and lit as baked_lit draws its bake: the same colour, and the normal of
// the displaced surface P + 0.05 height(P) N from the height's analytic gradient (snoise_grad of
// noise/simplex3d_grad.glsl, octave by octave: d/dP snoise(f P) = f G(f P)). N is the face normal
// from the position's screen derivatives, cross(dFdx(P), dFdy(P)) (outward on front faces), and
// n = normalize(N - A (g - (g.N) N)), the gradient's part along the surface taken away. For
// bench/bake_study.cpp's lit live-against-baked comparison.
varying vec3 P;
void main(void) {
    vec3 G1, G2, G3;
    float n = snoise_grad(3.0 * P, G1) + 0.5 * snoise_grad(6.0 * P, G2) + 0.25 * snoise_grad(12.0 * P, G3);
    float h = 0.5 + 0.25 * n;
    vec3 g = 0.25 * (3.0 * G1 + 3.0 * G2 + 3.0 * G3);
    vec3 N = normalize(cross(dFdx(P), dFdy(P)));
    vec3 bumped = normalize(N - 0.05 * (g - dot(g, N) * N));
    vec3 L = vec3(0.2873479, 0.7662610, 0.5746958);
    float diffuse = max(dot(bumped, L), 0.0);
    vec3 color = mix(vec3(0.35, 0.25, 0.2), vec3(0.85, 0.8, 0.7), h);
    gl_FragColor = vec4(color * (0.2 + 0.8 * diffuse), 1.0);
}
