// Seed 002 ("Noise is Beautiful"), lines 44-46: the sine hash ("trash bits"), unchanged. Shown as
// 32 cells across the plane: the seed says how to hash, not what it drew.
varying vec2 st;
float cellnoise_sin(vec2 p) {
    return fract(sin(dot(p, vec2(12.9898, 78.233))) * 43758.5453);
}
void main(void) {
    gl_FragColor = vec4(vec3(cellnoise_sin(floor(st * 32.0))), 1.0);
}
