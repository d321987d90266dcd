// A stone-like colour from noise_bumps_height.glsl's height: dark in the hollows, light on the
// bumps. Unlit: `quadshade bake --maps color,height,normal` bakes this colour, the height and the
// normal map the height gives, and `baked_lit` lights them.
varying vec3 P;
void main(void) {
    float h = height(P);
    gl_FragColor = vec4(mix(vec3(0.35, 0.25, 0.2), vec3(0.85, 0.8, 0.7), h), 1.0);
}
