// OpenGL ES Pixel Shaders Tutorial, "Procedural Textures: Square Grid": the square viewport cut
// into 2x2 tiles of one random grey each.
void main(void) {
    vec2 position = gl_FragCoord.xy/uResolution.xx;
    if ((position.x>1.) || (position.y>1.)) {
        discard;
    }
    float tiles = 2.;
    position = floor(position*tiles);
    float n = randomNoise(position);
    gl_FragColor = vec4(vec3(n), 1.);
}
