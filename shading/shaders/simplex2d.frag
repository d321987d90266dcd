// Listing 1.3: 2D simplex noise as grey.
varying vec2 st;
void main(void) {
    gl_FragColor = vec4(vec3(0.5 + 0.5 * snoise(st)), 1.0);
}
