// OpenGL ES Pixel Shaders Tutorial, "Procedural Textures: Square Grid": the square viewport (one
// unit of position is the window's width), what lies above it discarded, and per-pixel random noise
// in it; the output line is the tutorial's ("Procedural Textures: Smooth Noise").
void main(void) {
    vec2 position = gl_FragCoord.xy/uResolution.xx;
    if ((position.x>1.) || (position.y>1.)) {
        discard;
    }
    float n = randomNoise(position);
    gl_FragColor = vec4(vec3(n), 1.);
}
