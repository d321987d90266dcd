// Probe of quad derivatives at silhouettes: the derivatives of an object-space position, which on
// a sphere's rim come from helper lanes extrapolated far outside their triangle.
// dFdx(P) in red, green, blue; |dFdy(P)| in alpha (never 0 where drawn).
varying vec3 P;
void main(void) {
    gl_FragColor = vec4(dFdx(P), length(dFdy(P)));
}
