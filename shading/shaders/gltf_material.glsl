// What both stages of the default material (gltf_material.h) share: its light, and sRGB.

// One directional light fixed to the camera, coming from above and to the right of the viewer
// (the unit vector towards it, in view space), and an ambient term: Lambert's law on a normal.
const vec3 kLight = vec3(0.36, 0.48, 0.8);
float lambert(vec3 n) {
    return 0.3 + 0.7 * max(dot(n, kLight), 0.0);
}

// glTF's base colour textures are sRGB-encoded and everything else is linear: texels are decoded
// before they are multiplied, and the lit colour is encoded again for display.
float decode_srgb(float c) {
    return c <= 0.04045 ? c * 0.0773993808 : pow((c + 0.055) * 0.947867299, 2.4);
}
float encode_srgb(float c) {
    return c <= 0.0031308 ? c * 12.92 : 1.055 * pow(c, 0.416666667) - 0.055;
}
