varying vec2 st;
float h(float x) { return fract(sin(x * 12.9898) * 43758.5453); }
void main() {
    vec2 c = floor(st * 8.0);
    float s = 0.0;
    for (int i = -1; i <= 1; i++) {
        for (int j = -1; j <= 1; j++) {
            float p = h(c.x + float(i)) + h(c.y + float(j)) * h(c.x * c.y);
            c.x += p;
            s += p;
        }
    }
    gl_FragColor = vec4(s);
}
