// Probe of the driver's quad derivatives: a nonlinear function of window position, its dFdx and
// dFdy written to a float target (red, green), the function itself in blue.
void main(void) {
    vec2 p = gl_FragCoord.xy;
    float v = p.x * p.x + 100.0 * p.y * p.y + 10.0 * p.x * p.y;
    gl_FragColor = vec4(dFdx(v), dFdy(v), v, 1.0);
}
