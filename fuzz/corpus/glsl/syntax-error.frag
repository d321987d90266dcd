varying vec2 st;
void main() { gl_FragColor = vec4(st, ; }
