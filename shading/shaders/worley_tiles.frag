// Table 1.1 "Worley tiles" (Figure 1.5 bottom): cell borders from F2 - F1, widened by the
// distance between the two nearest points, roughened by fine cellular noise, anti-aliased.
varying vec2 st;
void main(void) {
    vec4 d1d2;
    vec2 F = cellular_vectors(st * 8.0, d1d2);
    float thresh = 0.05 * length(d1d2.xy - d1d2.zw) / (F.x + F.y);
    float f = F.y - F.x + (0.5 - cellular(st * 64.0).y) * thresh;
    gl_FragColor = vec4(vec3(aastep(thresh, f)), 1.0);
}
