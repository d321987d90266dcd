// Figure 1.1 ground plane: three octaves of flow noise, each advected by the gradients before it.
uniform float time;
varying vec2 p;
void main(void) {
    vec2 g1, g2;
    float n1 = srdnoise(p * 0.5, 0.2 * time, g1);
    float n2 = srdnoise(p * 2.0 + g1 * 0.5, 0.51 * time, g2);
    float n3 = srdnoise(p * 4.0 + g1 * 0.5 + g2 * 0.25, 0.77 * time, g2);
    float n = n1 + 0.75 * n2 + 0.5 * n3;
    gl_FragColor = vec4(vec3(0.4, 0.5, 0.6) + vec3(n), 1.0);
}
