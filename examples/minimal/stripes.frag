// Diagonal stripes whose edges are anti-aliased over the width of a pixel (fwidth). The vertex
// stage is quadshade's plane_st.vert: st = gl_MultiTexCoord0.st.
varying vec2 st;
void main(void) {
    float ramp = abs(fract(8.0 * (st.x + st.y)) * 2.0 - 1.0);
    float w = 0.7 * fwidth(ramp);
    float stripe = smoothstep(0.5 - w, 0.5 + w, ramp);
    gl_FragColor = vec4(mix(vec3(0.9, 0.3, 0.1), vec3(0.1, 0.2, 0.5), stripe), 1.0);
}
