// Noise is Beautiful (notes), "Trash Bits": the sine hash, unchanged. Shown as
// 32 cells across the plane: the notes say how to hash, not what they drew.
varying vec2 st;
float cellnoise_sin(vec2 p) {
    return fract(sin(dot(p, vec2(12.9898, 78.233))) * 43758.5453);
}
void main(void) {
    gl_FragColor = vec4(vec3(cellnoise_sin(floor(st * 32.0))), 1.0);
}
