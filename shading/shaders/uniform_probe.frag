// Probe: a shader's own uniforms of every kind, set from the material's extras.uniforms, from
// --uniform on the command line, or left at their initializers; uResolution is the frame's size
// in pixels. Bands of uTint over cells of a rotated, warped, scaled window position.
uniform float uScale = 4.0;
uniform vec3 uTint = vec3(1.0, 0.5, 0.2);
uniform int uBands = 3;
uniform ivec2 uCells = ivec2(2, 5);
uniform uint uSeed = 7u;
uniform mat2 uRotate = mat2(1.0);
uniform mat3 uWarp = mat3(1.0);
uniform vec2 uResolution;

void main(void) {
    vec2 p = gl_FragCoord.xy / uResolution - 0.5;
    vec2 q = uRotate * p * uScale;
    vec3 w = uWarp * vec3(q, 1.0);
    ivec2 cell = ivec2(floor(abs(w.xy))) * uCells;
    int bands = max(uBands, 1);
    int band = int((uint(cell.x + cell.y) * uSeed) % uint(bands));
    gl_FragColor = vec4(uTint * (float(band + 1) / float(bands)), fract(w.z));
}
