// Noise is Beautiful (notes), "Scatterings", "Example: Sample Code": the nearest
// jittered point of a 3x3x3 search, coloured by 1 - 2 d1^2. Shadertoy code, unchanged; its inputs
// are mapped onto quadshade's by the two #defines: iTime is the `time` uniform (the scene's time
// in seconds), iResolution the window's size in pixels, which quadshade sets in the uResolution
// uniform (a vec2: Shadertoy's vec3 adds the pixel aspect ratio, 1). main() calls mainImage with
// gl_FragCoord.xy, as Shadertoy does. gradient(vec3) is noise/permute_polynomial.glsl's (the
// notes', printed in this same listing).
uniform float time;
uniform vec2 uResolution;
#define iTime time
#define iResolution vec3(uResolution, 1.0)
void mainImage( out vec4 fragColor, in vec2 fragCoord )
{
    vec2 uv = fragCoord/iResolution.xy;
    vec3 xyz = vec3(uv * 15., iTime);
    // Config
    float jitter = 0.5f;
    // Determine the cell we are in
    vec3 cur_cell = floor(xyz);
    float c = 0.;
    float d1 = 100.;
    // Iterate through the neighbors of the cell
    for (int i = -1; i <= 1; i++) {
        for (int j = -1; j <= 1; j++) {
            for (int k = -1; k <= 1; k++) {
                vec3 cell = cur_cell + vec3(i,j,k);
                // Compute the pseudorandom point from that cell
                vec3 jitter_vec = gradient(cell) * jitter;
                vec3 point = cell + vec3(0.5) + jitter_vec;
                // Compute distance to this point
                float d = length(point - xyz);
                // Update d1, d2. D1 is distance to closest, D2
                // is 2nd closest
                d1 = (d < d1) ? d : d1;
            }
        }
    }
    c = 1. - 2. * d1 * d1;
    // Output to screen
    vec3 color = mix(vec3(0.1), vec3(0.8, 0.1, 0.2), c);
    fragColor = vec4(color, 1.);
}
void main(void) {
    mainImage(gl_FragColor, gl_FragCoord.xy);
}
