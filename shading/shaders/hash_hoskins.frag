// Noise is Beautiful (notes), "Ad-Hoc Float Hash": Dave Hoskins' hash12, unchanged. Shown as 32
// cells across the plane: the notes say how to hash, not what they drew.
varying vec2 st;
float hash12(vec2 p) {
    vec3 p3 = fract(vec3(p.xyx) * 0.1031);
    p3 += dot(p3, p3.yzx + 33.33);
    return fract((p3.x + p3.y) * p3.z);
}
void main(void) {
    gl_FragColor = vec4(vec3(hash12(floor(st * 32.0))), 1.0);
}
