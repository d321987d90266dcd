// probe: textureSize and texelFetch of teximage (GLSL 1.30). textureSize at a level from -1
// (below the base) to 4 (past the last level of most textures), the same for each 4-pixel column
// group (llvmpipe answers a whole 4x2 block of fragments with the level of its first: GLSL asks
// for each fragment's, which quadshade gives); texelFetch at a level per pixel from -1 to 2, at
// texel coordinates from 2 before that size to 2 past it. Even columns show the fetched texel
// (alpha kept above 1/2: it is the coverage), odd columns the size; every value is exact in a
// float target.
uniform sampler2D teximage;
void main(void) {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    int level = (pixel.x / 4) % 6 - 1;
    ivec2 size = textureSize(teximage, level);
    ivec2 texel = (pixel * ivec2(3, 5)) % (size + 5) - 2;
    vec4 c = texelFetch(teximage, texel, (pixel.x + pixel.y) % 4 - 1);
    if (pixel.x % 2 == 0) {
        gl_FragColor = vec4(c.rgb, 0.75 + 0.25 * c.a);
    } else {
        gl_FragColor = vec4(vec2(size) / 1024.0, float(level + 1) / 8.0, 1.0);
    }
}
