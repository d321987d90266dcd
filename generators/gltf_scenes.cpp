#include "generators/gltf_scenes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "generators/gltf_writer.h"
#include "images/image_io.h"

namespace qs {

namespace {

using json = nlohmann::json;
constexpr double kPi = std::numbers::pi;

// A mesh's vertices (positions, normals, texture coordinates) and triangles.
struct Geometry {
    std::vector<float> p, n, uv;
    std::vector<std::uint16_t> index;
    std::size_t vertices() const { return p.size() / 3; }
    void vertex(glm::vec3 pos, glm::vec3 normal, glm::vec2 st) {
        p.insert(p.end(), {pos.x, pos.y, pos.z});
        n.insert(n.end(), {normal.x, normal.y, normal.z});
        uv.insert(uv.end(), {st.x, st.y});
    }
};

// A unit sphere, v = 0 at its top (+y), as glTF's UV (0, 0) is an image's top.
Geometry sphere(int bands, int steps) {
    Geometry g;
    for (int b = 0; b <= bands; ++b) {
        for (int s = 0; s <= steps; ++s) {
            const double theta = kPi * b / bands, phi = 2 * kPi * s / steps;
            const glm::vec3 d(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                              float(-std::sin(theta) * std::sin(phi)));
            g.vertex(d, d, {float(s) / float(steps), float(b) / float(bands)});
        }
    }
    for (int b = 0; b < bands; ++b) {
        for (int s = 0; s < steps; ++s) {
            const auto at = [&](int bb, int ss) { return std::uint16_t(bb * (steps + 1) + ss); };
            if (b > 0) g.index.insert(g.index.end(), {at(b, s), at(b + 1, s), at(b, s + 1)});
            if (b < bands - 1) g.index.insert(g.index.end(), {at(b, s + 1), at(b + 1, s), at(b + 1, s + 1)});
        }
    }
    return g;
}

// The cube [-1, 1]^3, four vertices a face, each face's texture upright seen from outside.
Geometry box() {
    Geometry g;
    const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const glm::vec3& nrm : normals) {
        // u and v span the face so that u x v = n (counter-clockwise from outside).
        const glm::vec3 up = std::abs(nrm.y) > 0.5f ? glm::vec3(0, 0, -nrm.y) : glm::vec3(0, 1, 0);
        const glm::vec3 u = glm::cross(up, nrm), v = up;
        const auto base = std::uint16_t(g.vertices());
        const glm::vec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (const glm::vec2& c : corners) {
            g.vertex(nrm + c.x * u + c.y * v, nrm, {0.5f + 0.5f * c.x, 0.5f - 0.5f * c.y});
        }
        g.index.insert(g.index.end(), {base, std::uint16_t(base + 1), std::uint16_t(base + 2), base,
                                       std::uint16_t(base + 2), std::uint16_t(base + 3)});
    }
    return g;
}

// A torus around +y: major radius R, minor r.
Geometry torus(float R, float r, int nu, int nv) {
    Geometry g;
    for (int j = 0; j <= nv; ++j) {
        for (int i = 0; i <= nu; ++i) {
            const double a = 2 * kPi * i / nu, b = 2 * kPi * j / nv;
            const glm::vec3 centre(float(R * std::cos(a)), 0.0f, float(-R * std::sin(a)));
            const glm::vec3 d(float(std::cos(b) * std::cos(a)), float(std::sin(b)), float(-std::cos(b) * std::sin(a)));
            g.vertex(centre + r * d, d, {float(i) / float(nu), float(j) / float(nv)});
        }
    }
    for (int j = 0; j < nv; ++j) {
        for (int i = 0; i < nu; ++i) {
            const auto at = [&](int ii, int jj) { return std::uint16_t(jj * (nu + 1) + ii); };
            g.index.insert(g.index.end(),
                           {at(i, j), at(i + 1, j), at(i, j + 1), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
    return g;
}

// A cylinder around +y, radius 1, from y = -1 to 1, with its caps.
Geometry cylinder(int steps) {
    Geometry g;
    for (int s = 0; s <= steps; ++s) {
        const double a = 2 * kPi * s / steps;
        const glm::vec3 d(float(std::cos(a)), 0.0f, float(-std::sin(a)));
        g.vertex(d + glm::vec3(0, -1, 0), d, {float(s) / float(steps), 1.0f});
        g.vertex(d + glm::vec3(0, 1, 0), d, {float(s) / float(steps), 0.0f});
    }
    for (int s = 0; s < steps; ++s) {
        const auto b = std::uint16_t(2 * s);
        g.index.insert(g.index.end(), {b, std::uint16_t(b + 2), std::uint16_t(b + 1), std::uint16_t(b + 1),
                                       std::uint16_t(b + 2), std::uint16_t(b + 3)});
    }
    for (const float y : {-1.0f, 1.0f}) {
        const auto centre = std::uint16_t(g.vertices());
        g.vertex({0, y, 0}, {0, y, 0}, {0.5f, 0.5f});
        for (int s = 0; s <= steps; ++s) {
            const double a = 2 * kPi * s / steps;
            g.vertex({float(std::cos(a)), y, float(-std::sin(a))}, {0, y, 0},
                     {0.5f + 0.5f * float(std::cos(a)), 0.5f + 0.5f * float(std::sin(a))});
        }
        for (int s = 0; s < steps; ++s) {
            const auto a = std::uint16_t(centre + 1 + s), b = std::uint16_t(centre + 2 + s);
            if (y > 0) {
                g.index.insert(g.index.end(), {centre, a, b});
            } else {
                g.index.insert(g.index.end(), {centre, b, a});
            }
        }
    }
    return g;
}

// The square [-1, 1]^2 at z = 0 facing +z, its texture upright.
Geometry square() {
    Geometry g;
    g.vertex({-1, -1, 0}, {0, 0, 1}, {0, 1});
    g.vertex({1, -1, 0}, {0, 0, 1}, {1, 1});
    g.vertex({1, 1, 0}, {0, 0, 1}, {1, 0});
    g.vertex({-1, 1, 0}, {0, 0, 1}, {0, 0});
    g.index = {0, 1, 2, 0, 2, 3};
    return g;
}

// The attributes a primitive gets from `g`: POSITION always, NORMAL and TEXCOORD_0 if asked.
json attributes(GltfWriter& w, const Geometry& g, bool normals, bool uvs) {
    json a = {{"POSITION", w.data(g.p, kFloatType, "VEC3", false, true)}};
    if (normals) a["NORMAL"] = w.data(g.n, kFloatType, "VEC3");
    if (uvs) a["TEXCOORD_0"] = w.data(g.uv, kFloatType, "VEC2");
    return a;
}

json primitive(GltfWriter& w, const Geometry& g, int material, bool normals = true, bool uvs = true) {
    json p = {{"attributes", attributes(w, g, normals, uvs)}, {"indices", w.data(g.index, kUShort, "SCALAR")}};
    if (material >= 0) p["material"] = material;
    return p;
}

int mesh(GltfWriter& w, const std::string& name, json primitives) {
    return w.add("meshes", {{"name", name}, {"primitives", std::move(primitives)}});
}

const glm::quat kNoRotation(1, 0, 0, 0);  // w, x, y, z

json trs(glm::vec3 t, glm::quat r = kNoRotation, glm::vec3 s = glm::vec3(1)) {
    json n;
    if (t != glm::vec3(0)) n["translation"] = {t.x, t.y, t.z};
    if (r != kNoRotation) n["rotation"] = {r.x, r.y, r.z, r.w};
    if (s != glm::vec3(1)) n["scale"] = {s.x, s.y, s.z};
    return n;
}

glm::quat about(float degrees, glm::vec3 axis) { return glm::angleAxis(glm::radians(degrees), glm::normalize(axis)); }

int node(GltfWriter& w, const std::string& name, int mesh_index, json transform, std::vector<int> children = {}) {
    json n = std::move(transform);
    if (n.is_null()) n = json::object();
    n["name"] = name;
    if (mesh_index >= 0) n["mesh"] = mesh_index;
    if (!children.empty()) n["children"] = children;
    return w.add("nodes", n);
}

// A camera node at `eye` looking at `target` (+y up), as TRS, under a parent rotated by
// `parent` (its translation, rotation).
int camera(GltfWriter& w, const std::string& name, glm::vec3 eye, glm::vec3 target, json camera_json,
           glm::quat parent = glm::quat(1, 0, 0, 0)) {
    const int c = w.add("cameras", std::move(camera_json));
    const glm::mat4 local =
        glm::mat4_cast(glm::inverse(parent)) * glm::inverse(glm::lookAt(eye, target, glm::vec3(0, 1, 0)));
    json n = trs(glm::vec3(local[3]), glm::normalize(glm::quat_cast(glm::mat3(local))));
    n["name"] = name;
    n["camera"] = c;
    return w.add("nodes", n);
}

json perspective(double yfov, double znear, double zfar, double aspect = 0.0) {
    json p = {{"yfov", yfov}, {"znear", znear}, {"zfar", zfar}};
    if (aspect > 0.0) p["aspectRatio"] = aspect;
    return {{"type", "perspective"}, {"perspective", p}};
}

// The clear colour's alpha is 0, so that coverage (alpha) tells what was drawn.
void scene(GltfWriter& w, std::vector<int> roots, int width, int height, glm::vec4 clear = {0.18f, 0.2f, 0.24f, 0.0f}) {
    w["scenes"] =
        json::array({{{"nodes", roots},
                      {"extras", {{"clear_color", {clear.r, clear.g, clear.b, clear.a}}, {"size", {width, height}}}}}});
    w["scene"] = 0;
}

json factor(double r, double g, double b, double a = 1.0) { return {{"baseColorFactor", {r, g, b, a}}}; }

int material(GltfWriter& w, const std::string& name, json pbr, json more = json::object()) {
    json m = std::move(more);
    m["name"] = name;
    m["pbrMetallicRoughness"] = std::move(pbr);
    return w.add("materials", m);
}

// A texture of image file `uri` (relative to the scene) with a sampler.
int texture(GltfWriter& w, const std::string& uri, int mag, int min, int wrap_s = 10497, int wrap_t = 10497) {
    const int image = w.add("images", {{"uri", uri}});
    const int sampler =
        w.add("samplers", {{"magFilter", mag}, {"minFilter", min}, {"wrapS", wrap_s}, {"wrapT", wrap_t}});
    return w.add("textures", {{"source", image}, {"sampler", sampler}});
}
constexpr int kNearest = 9728, kLinear = 9729, kTrilinear = 9987, kClamp = 33071, kMirrored = 33648;

// ---- images ---------------------------------------------------------------------------------

Image8 image(int size, auto texel) {
    Image8 img{size, size, std::vector<std::uint8_t>(std::size_t(size) * std::size_t(size) * 4)};
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const glm::vec4 c = texel((x + 0.5f) / float(size), (y + 0.5f) / float(size));
            for (int k = 0; k < 4; ++k) {
                img.rgba[(std::size_t(y) * std::size_t(size) + std::size_t(x)) * 4 + std::size_t(k)] =
                    std::uint8_t(std::lround(std::clamp(c[k], 0.0f, 1.0f) * 255.0f));
            }
        }
    }
    return img;
}

// Eight by eight squares of warm and cool colours, shaded along u.
Image8 checker_image() {
    return image(64, [](float u, float v) {
        const bool odd = (int(u * 8) + int(v * 8)) % 2;
        return odd ? glm::vec4(0.95f, 0.75f - 0.4f * u, 0.2f, 1.0f) : glm::vec4(0.15f, 0.35f + 0.4f * v, 0.8f, 1.0f);
    });
}

// A leaf's outline in alpha (1 inside, falling to 0 across its edge), veins darker.
Image8 leaf_image() {
    return image(64, [](float u, float v) {
        const float x = 2 * u - 1, y = 2 * v - 1;
        const float width = 0.55f * (1.0f - y * y);
        const float inside = std::clamp((width - std::abs(x)) * 6.0f + 0.5f, 0.0f, 1.0f);
        const bool vein = std::abs(x) < 0.04f || std::abs(std::abs(x) - (y + 1.0f) * 0.3f) < 0.03f;
        return glm::vec4(vein ? 0.2f : 0.3f, vein ? 0.45f : 0.7f + 0.2f * y, 0.15f, inside);
    });
}

// Which way is up and right: a grid of cells, red growing along u and green along v, an arrow
// pointing to +u in the top-left quarter.
Image8 grid_image() {
    return image(32, [](float u, float v) {
        const bool line = std::fmod(u * 4, 1.0f) < 0.12f || std::fmod(v * 4, 1.0f) < 0.12f;
        const float ax = u * 2, ay = v * 2;
        const bool arrow = ax < 1 && ay < 1 &&
                           ((ax > 0.15f && ax < 0.6f && std::abs(ay - 0.5f) < 0.08f) ||
                            (ax >= 0.6f && ax < 0.9f && std::abs(ay - 0.5f) < 0.9f - ax));
        if (arrow) return glm::vec4(1.0f, 1.0f, 1.0f, 1.0f);
        return line ? glm::vec4(0.1f, 0.1f, 0.1f, 1.0f) : glm::vec4(u, v, 0.5f, 1.0f);
    });
}

// Wood: dark and light rings along u, bent.
Image8 wood_image() {
    return image(64, [](float u, float v) {
        const float ring = 0.5f + 0.5f * float(std::sin((u * 9.0f + 0.6f * std::sin(v * 6.0f)) * 2.0f * float(kPi)));
        return glm::vec4(0.45f + 0.2f * ring, 0.28f + 0.12f * ring, 0.12f + 0.05f * ring, 1.0f);
    });
}

// ---- the scenes -----------------------------------------------------------------------------

// The default material's base colour: a factor alone, a texture times a factor, COLOR_0 as
// normalized bytes and as floats, lit per vertex (NORMAL), flat (no NORMAL), unlit
// (KHR_materials_unlit), the back of a double-sided surface, and a primitive without a material.
void default_material(const std::filesystem::path& dir) {
    GltfWriter w;
    w.use_extension("KHR_materials_unlit");
    const int checker = texture(w, "textures/checker.png", kLinear, kTrilinear);
    const int textured = material(
        w, "Checker", {{"baseColorFactor", {1.0, 0.85, 0.7, 1.0}}, {"baseColorTexture", {{"index", checker}}}});
    const int red = material(w, "Red", factor(0.8, 0.05, 0.04));
    const int white = material(w, "White", factor(1.0, 1.0, 1.0));
    const int sign = material(w, "Sign", {{"baseColorTexture", {{"index", checker}}}},
                              {{"doubleSided", true}, {"extensions", {{"KHR_materials_unlit", json::object()}}}});
    const int blue = material(w, "Blue", factor(0.2, 0.45, 0.9), {{"doubleSided", true}});
    const Geometry ball = sphere(16, 24), cube = box(), ring = torus(0.7f, 0.28f, 32, 16), plate = square();

    std::vector<int> roots;
    roots.push_back(node(w, "Textured sphere", mesh(w, "Sphere", json::array({primitive(w, ball, textured)})),
                         trs({-2.6f, 0.75f, 0}, about(30, {0, 1, 0}), glm::vec3(0.8f))));
    roots.push_back(node(w, "Flat box", mesh(w, "Box", json::array({primitive(w, cube, red, false, false)})),
                         trs({-0.9f, 0.75f, 0}, about(35, {1, 1, 0}), glm::vec3(0.6f))));
    // Vertex colours as normalized unsigned bytes, RGB: a hue around the ring.
    std::vector<std::uint8_t> hues;
    for (std::size_t i = 0; i < ring.vertices(); ++i) {
        const float h = ring.uv[2 * i] * 6.0f;
        for (int k = 0; k < 3; ++k) {
            const float c = std::clamp(std::abs(std::fmod(h + float(k) * 2.0f, 6.0f) - 3.0f) - 1.0f, 0.0f, 1.0f);
            hues.push_back(std::uint8_t(std::lround(c * 255.0f)));
        }
    }
    json colours = primitive(w, ring, white, true, false);
    colours["attributes"]["COLOR_0"] = w.data(hues, kUByte, "VEC3", true);
    roots.push_back(node(w, "Vertex colours", mesh(w, "Ring", json::array({colours})),
                         trs({0.9f, 0.75f, 0}, about(70, {1, 0, 0}))));
    // Float RGBA vertex colours and no material: glTF's default material, white and single-sided.
    std::vector<float> rgba;
    for (std::size_t i = 0; i < ball.vertices(); ++i) {
        rgba.insert(rgba.end(), {0.5f + 0.5f * ball.n[3 * i], 0.5f + 0.5f * ball.n[3 * i + 1],
                                 0.5f + 0.5f * ball.n[3 * i + 2], 1.0f});
    }
    json bare = primitive(w, ball, -1, true, false);
    bare["attributes"]["COLOR_0"] = w.data(rgba, kFloatType, "VEC4");
    roots.push_back(node(w, "No material", mesh(w, "Bare sphere", json::array({bare})),
                         trs({2.6f, 0.75f, 0}, kNoRotation, glm::vec3(0.8f))));
    // Both seen from behind: the unlit sign mirrored, the lit plate with its normal reversed.
    roots.push_back(node(w, "Unlit sign", mesh(w, "Sign", json::array({primitive(w, plate, sign)})),
                         trs({-1.4f, -1.0f, 0}, about(160, {0, 1, 0}), {1.1f, 0.6f, 1})));
    roots.push_back(node(w, "Back of a plate", mesh(w, "Plate", json::array({primitive(w, plate, blue)})),
                         trs({1.4f, -1.0f, 0}, about(200, {0, 1, 0}) * about(-25, {1, 0, 0}), {1.1f, 0.6f, 1})));
    roots.push_back(camera(w, "Camera", {0.0f, 1.0f, 7.5f}, {0, 0, 0}, perspective(0.62, 1.0, 30.0)));
    scene(w, roots, 256, 160);
    w.write(dir / "default-material.gltf");
}

// alphaMode: OPAQUE ignoring a factor's alpha, MASK cutting a texture's alpha at alphaCutoff, and
// BLEND: three overlapping panes written nearest first, drawn back to front after the rest.
void alpha_modes(const std::filesystem::path& dir) {
    GltfWriter w;
    const int leaf = texture(w, "textures/leaf.png", kLinear, kTrilinear, kClamp, kClamp);
    const int floor = material(w, "Floor", factor(0.55, 0.55, 0.5));
    const int mask = material(w, "Leaf", {{"baseColorTexture", {{"index", leaf}}}},
                              {{"alphaMode", "MASK"}, {"alphaCutoff", 0.4}, {"doubleSided", true}});
    const int opaque = material(w, "Opaque despite alpha", factor(0.9, 0.55, 0.1, 0.25));
    const Geometry plate = square(), cube = box();
    std::vector<int> roots;
    roots.push_back(node(w, "Floor", mesh(w, "Floor", json::array({primitive(w, cube, floor)})),
                         trs({0, -1.3f, -1.0f}, kNoRotation, {3.5f, 0.2f, 2.5f})));
    roots.push_back(node(w, "Leaf", mesh(w, "Leaf", json::array({primitive(w, plate, mask)})),
                         trs({-1.9f, 0.2f, 0.3f}, about(-20, {0, 1, 0}) * about(15, {0, 0, 1}), glm::vec3(0.9f))));
    roots.push_back(node(w, "Opaque", mesh(w, "Opaque", json::array({primitive(w, plate, opaque)})),
                         trs({1.9f, 0.2f, -0.5f}, about(25, {0, 1, 0}), glm::vec3(0.7f))));
    const glm::vec4 pane_colours[3] = {{0.9f, 0.1f, 0.1f, 0.5f}, {0.1f, 0.8f, 0.2f, 0.6f}, {0.15f, 0.3f, 1.0f, 0.4f}};
    for (int i = 0; i < 3; ++i) {  // nearest first in the file
        const glm::vec4 c = pane_colours[i];
        const int m = material(w, "Pane " + std::to_string(i), factor(c.r, c.g, c.b, c.a),
                               {{"alphaMode", "BLEND"}, {"doubleSided", true}});
        roots.push_back(node(w, "Pane " + std::to_string(i),
                             mesh(w, "Pane " + std::to_string(i), json::array({primitive(w, plate, m)})),
                             trs({-0.35f + 0.35f * float(i), 0.1f * float(i), 1.0f - 0.8f * float(i)},
                                 about(10.0f * float(i), {0, 1, 0}), glm::vec3(0.75f))));
    }
    // A blended sphere, lit, crossing the floor: its far side drawn over the floor too.
    const int glass = material(w, "Glass", factor(0.7, 0.85, 1.0, 0.35), {{"alphaMode", "BLEND"}});
    roots.push_back(node(w, "Glass", mesh(w, "Glass", json::array({primitive(w, sphere(12, 18), glass)})),
                         trs({1.3f, -1.0f, 0.6f}, kNoRotation, glm::vec3(0.55f))));
    roots.push_back(camera(w, "Camera", {0.4f, 1.4f, 6.0f}, {0, -0.2f, 0}, perspective(0.7, 1.0, 20.0)));
    scene(w, roots, 192, 144);
    w.write(dir / "alpha-modes.gltf");
}

// Texture coordinate sets and KHR_texture_transform: a texture on TEXCOORD_1, one on TEXCOORD_2
// through the extension's texCoord, offset, rotation and scale, and a mirrored nearest sampler.
void texcoord_sets(const std::filesystem::path& dir) {
    GltfWriter w;
    w.use_extension("KHR_texture_transform");
    const int grid = texture(w, "textures/grid.png", kLinear, kTrilinear);
    const int mirrored = texture(w, "textures/grid.png", kNearest, kNearest, kMirrored, kMirrored);
    const Geometry plate = square();
    // TEXCOORD_0 everywhere a corner of the texture, the real mapping in the other sets.
    std::vector<float> corner(plate.uv.size(), 0.1f), twice;
    for (float c : plate.uv) twice.push_back(2.0f * c - 0.5f);
    auto quad = [&](const std::string& name, json base_texture, const std::vector<float>& set1,
                    const std::vector<float>& set2) {
        const int m = material(w, name, {{"baseColorTexture", std::move(base_texture)}});
        json p = primitive(w, plate, m, true, false);
        p["attributes"]["TEXCOORD_0"] = w.data(corner, kFloatType, "VEC2");
        if (!set1.empty()) p["attributes"]["TEXCOORD_1"] = w.data(set1, kFloatType, "VEC2");
        if (!set2.empty()) p["attributes"]["TEXCOORD_2"] = w.data(set2, kFloatType, "VEC2");
        return mesh(w, name, json::array({p}));
    };
    std::vector<int> roots;
    roots.push_back(node(w, "Set 1", quad("TEXCOORD_1", {{"index", grid}, {"texCoord", 1}}, plate.uv, {}),
                         trs({-2.4f, 0.8f, 0}, kNoRotation, glm::vec3(0.75f))));
    roots.push_back(
        node(w, "Set 2",
             quad("TEXCOORD_2", {{"index", grid}, {"extensions", {{"KHR_texture_transform", {{"texCoord", 2}}}}}},
                  corner, plate.uv),
             trs({-0.8f, 0.8f, 0}, kNoRotation, glm::vec3(0.75f))));
    roots.push_back(
        node(w, "Transform",
             quad("Transformed",
                  {{"index", grid},
                   {"texCoord", 1},
                   {"extensions",
                    {{"KHR_texture_transform", {{"offset", {0.25, -0.1}}, {"rotation", 0.4}, {"scale", {1.5, 2.0}}}}}}},
                  plate.uv, {}),
             trs({0.8f, 0.8f, 0}, kNoRotation, glm::vec3(0.75f))));
    roots.push_back(node(w, "Mirrored", quad("Mirrored nearest", {{"index", mirrored}, {"texCoord", 1}}, twice, {}),
                         trs({2.4f, 0.8f, 0}, kNoRotation, glm::vec3(0.75f))));
    // A receding plane: the transform's scale changes the level of detail as llvmpipe computes it.
    roots.push_back(node(
        w, "Floor",
        quad("Scaled floor",
             {{"index", grid}, {"texCoord", 1}, {"extensions", {{"KHR_texture_transform", {{"scale", {6.0, 3.0}}}}}}},
             plate.uv, {}),
        trs({0, -0.9f, -1.5f}, about(-80, {1, 0, 0}), {3.2f, 2.0f, 1})));
    roots.push_back(camera(w, "Camera", {0.0f, 0.6f, 5.5f}, {0, 0, 0}, perspective(0.75, 0.5, 30.0)));
    scene(w, roots, 192, 128);
    w.write(dir / "texcoord-sets.gltf");
}

// Primitive modes: a triangle strip (indexed), a fan (not indexed), triangles; and points and
// lines in the same mesh and in one of their own, skipped with one warning.
void primitive_modes(const std::filesystem::path& dir) {
    GltfWriter w;
    const int orange = material(w, "Orange", factor(1.0, 0.5, 0.1), {{"doubleSided", true}});
    const int teal = material(w, "Teal", factor(0.1, 0.7, 0.6));
    // A ribbon as a strip: pairs of vertices along a wave, normals from the wave.
    std::vector<float> strip_p, strip_n;
    std::vector<std::uint16_t> strip_i;
    for (int i = 0; i <= 16; ++i) {
        const float x = -2.0f + 0.25f * float(i), z = 0.4f * std::sin(1.5f * x), dz = 0.6f * std::cos(1.5f * x);
        const glm::vec3 n = glm::normalize(glm::vec3(-dz, 0.0f, 1.0f));
        for (const float y : {-0.35f, 0.35f}) {
            strip_p.insert(strip_p.end(), {x, y + 0.9f, z});
            strip_n.insert(strip_n.end(), {n.x, n.y, n.z});
        }
        strip_i.insert(strip_i.end(), {std::uint16_t(2 * i), std::uint16_t(2 * i + 1)});
    }
    json strip = {{"mode", 5},
                  {"material", orange},
                  {"attributes",
                   {{"POSITION", w.data(strip_p, kFloatType, "VEC3", false, true)},
                    {"NORMAL", w.data(strip_n, kFloatType, "VEC3")}}},
                  {"indices", w.data(strip_i, kUShort, "SCALAR")}};
    // A disc as a fan around its centre, not indexed, with vertex colours and no normals (flat).
    std::vector<float> fan_p = {-1.2f, -0.8f, 0.0f}, fan_c = {1, 1, 1, 1};
    for (int i = 0; i <= 12; ++i) {
        const double a = 2 * kPi * i / 12;
        fan_p.insert(fan_p.end(), {-1.2f + 0.8f * float(std::cos(a)), -0.8f + 0.8f * float(std::sin(a)),
                                   0.3f * float(std::sin(2 * a))});
        fan_c.insert(fan_c.end(), {float(0.5 + 0.5 * std::cos(a)), float(0.5 + 0.5 * std::sin(a)), 0.3f, 1.0f});
    }
    json fan = {{"mode", 6},
                {"material", teal},
                {"attributes",
                 {{"POSITION", w.data(fan_p, kFloatType, "VEC3", false, true)},
                  {"COLOR_0", w.data(fan_c, kFloatType, "VEC4")}}}};
    const Geometry cube = box();
    json triangles = primitive(w, cube, teal);
    json points = {{"mode", 0}, {"attributes", {{"POSITION", w.data(fan_p, kFloatType, "VEC3", false, true)}}}};
    json lines = {{"mode", 1}, {"attributes", {{"POSITION", w.data(strip_p, kFloatType, "VEC3", false, true)}}}};
    const int shapes = mesh(w, "Shapes", json::array({strip, fan, points, lines}));
    const int outline = mesh(
        w, "Outline",
        json::array({{{"mode", 2}, {"attributes", {{"POSITION", w.data(fan_p, kFloatType, "VEC3", false, true)}}}}}));
    std::vector<int> roots;
    roots.push_back(node(w, "Shapes", shapes, json::object()));
    roots.push_back(node(w, "Box", mesh(w, "Box", json::array({triangles})),
                         trs({1.3f, -0.8f, 0}, about(30, {1, 1, 0}), glm::vec3(0.5f))));
    roots.push_back(node(w, "Outline", outline, trs({0, 0, 0.5f})));
    roots.push_back(camera(w, "Camera", {0.0f, 0.3f, 5.0f}, {0, 0, 0}, perspective(0.8, 0.5, 20.0)));
    scene(w, roots, 160, 120);
    w.write(dir / "primitive-modes.gltf");
}

// Animations of node transforms: LINEAR translation, STEP scale, CUBICSPLINE translation, LINEAR
// rotation by glTF's slerp (the third keyframe stored with the opposite sign: the short way is
// taken), a child under an animated parent, and the camera's node moving.
void animation(const std::filesystem::path& dir) {
    GltfWriter w;
    const int red = material(w, "Red", factor(0.85, 0.15, 0.1));
    const int green = material(w, "Green", factor(0.2, 0.75, 0.25));
    const int blue = material(w, "Blue", factor(0.2, 0.35, 0.9));
    const int gold = material(w, "Gold", factor(0.9, 0.7, 0.2));
    const int cube = mesh(w, "Cube", json::array({primitive(w, box(), red)}));
    const int ball = mesh(w, "Ball", json::array({primitive(w, sphere(12, 18), green)}));
    const int ring = mesh(w, "Ring", json::array({primitive(w, torus(0.6f, 0.2f, 24, 12), blue)}));
    const int spinner_mesh = mesh(w, "Spinner", json::array({primitive(w, box(), gold)}));
    const int moon = mesh(w, "Moon", json::array({primitive(w, sphere(8, 12), red)}));
    std::vector<int> roots;
    const int slider = node(w, "Slider", cube, trs({-2, 1, 0}, kNoRotation, glm::vec3(0.4f)));
    const int blinker = node(w, "Blinker", ball, trs({0, 1, 0}, kNoRotation, glm::vec3(0.5f)));
    const int spline = node(w, "Spline", ring, trs({2, 1, 0}, about(60, {1, 0, 0})));
    const int child = node(w, "Moon", moon, trs({1.6f, 0, 0}, kNoRotation, glm::vec3(0.6f)));
    const int spinner = node(w, "Spinner", spinner_mesh, trs({0, -0.9f, 0}, kNoRotation, glm::vec3(0.5f)), {child});
    const int cam = camera(w, "Camera", {0.0f, 0.8f, 7.0f}, {0, 0.2f, 0}, perspective(0.7, 1.0, 30.0));
    roots = {slider, blinker, spline, spinner, cam};
    json channels = json::array(), samplers = json::array();
    auto channel = [&](int target, const std::string& path, const std::string& interpolation, std::vector<float> times,
                       std::vector<float> values, const std::string& type) {
        const int input = w.data(times, kFloatType, "SCALAR", false, true);
        const int output = w.data(values, kFloatType, type);
        samplers.push_back({{"input", input}, {"output", output}, {"interpolation", interpolation}});
        channels.push_back({{"sampler", samplers.size() - 1}, {"target", {{"node", target}, {"path", path}}}});
    };
    channel(slider, "translation", "LINEAR", {0.0f, 1.0f, 2.0f}, {-2, 1, 0, -2, -0.3f, 0.5f, -1.4f, 0.4f, 1.0f},
            "VEC3");
    channel(blinker, "scale", "STEP", {0.0f, 0.5f, 1.0f, 1.5f},
            {0.5f, 0.5f, 0.5f, 0.25f, 0.7f, 0.25f, 0.6f, 0.6f, 0.6f, 0.3f, 0.3f, 0.3f}, "VEC3");
    // in-tangent, value, out-tangent for each keyframe
    channel(spline, "translation", "CUBICSPLINE", {0.0f, 1.0f, 2.0f}, {0,  0,  0, 2,    1,    0,     0,    3,  0,  //
                                                                       -2, 0,  0, 2.2f, 0.2f, 0.5f,  1.5f, -1, 0,  //
                                                                       0,  -2, 0, 1.6f, 0.9f, -0.5f, 0,    0,  0},
            "VEC3");
    const glm::quat q0(1, 0, 0, 0), q1 = about(120, {0, 1, 0}), q2 = -about(240, {0, 1, 0.3f});
    channel(spinner, "rotation", "LINEAR", {0.0f, 1.0f, 2.0f},
            {q0.x, q0.y, q0.z, q0.w, q1.x, q1.y, q1.z, q1.w, q2.x, q2.y, q2.z, q2.w}, "VEC4");
    channel(cam, "translation", "LINEAR", {0.0f, 2.0f}, {0.0f, 0.8f, 7.0f, 1.0f, 1.2f, 6.0f}, "VEC3");
    w.add("animations", {{"name", "Everything"}, {"channels", channels}, {"samplers", samplers}});
    scene(w, roots, 192, 144);
    w.write(dir / "animation.gltf");
}

// EXT_mesh_gpu_instancing: 125 cubes from one node, their rotations stored as normalized shorts,
// under a rotated parent.
void instancing(const std::filesystem::path& dir) {
    GltfWriter w;
    w.use_extension("EXT_mesh_gpu_instancing", true);
    const int m = material(w, "Painted", factor(0.3, 0.6, 0.9));
    const int cube = mesh(w, "Cube", json::array({primitive(w, box(), m)}));
    std::vector<float> t, s;
    std::vector<std::int16_t> r;
    for (int i = 0; i < 125; ++i) {
        const int x = i % 5, y = (i / 5) % 5, z = i / 25;
        t.insert(t.end(), {float(x - 2), float(y - 2), float(z - 2)});
        const glm::quat q = about(18.0f * float(i), {float(x + 1), float(y), 1.0f});
        for (const float c : {q.x, q.y, q.z, q.w}) r.push_back(std::int16_t(std::lround(c * 32767.0f)));
        const float k = 0.18f + 0.04f * float((x + 2 * y + 3 * z) % 4);
        s.insert(s.end(), {k, k, k});
    }
    json grid = trs({0, 0, 0}, about(25, {1, 0, 0}) * about(35, {0, 1, 0}));
    grid["name"] = "Instances";
    grid["mesh"] = cube;
    grid["extensions"] = {{"EXT_mesh_gpu_instancing",
                           {{"attributes",
                             {{"TRANSLATION", w.data(t, kFloatType, "VEC3")},
                              {"ROTATION", w.data(r, kShort, "VEC4", true)},
                              {"SCALE", w.data(s, kFloatType, "VEC3")}}}}}};
    const int instances = w.add("nodes", grid);
    const int cam = camera(w, "Camera", {0.0f, 0.0f, 10.0f}, {0, 0, 0}, perspective(0.7, 2.0, 20.0));
    scene(w, {instances, cam}, 160, 160);
    w.write(dir / "instancing.glb");
}

// KHR_mesh_quantization: positions as shorts scaled by their node, as normalized bytes, normals
// as normalized bytes, texture coordinates as normalized unsigned shorts, colours as normalized
// unsigned shorts.
void quantized(const std::filesystem::path& dir) {
    GltfWriter w;
    w.use_extension("KHR_mesh_quantization", true);
    const int checker = texture(w, "textures/checker.png", kLinear, kTrilinear);
    const int textured = material(w, "Checker", {{"baseColorTexture", {{"index", checker}}}});
    const int white = material(w, "White", factor(1, 1, 1));
    const Geometry ball = sphere(16, 24), ring = torus(0.7f, 0.3f, 32, 16);
    auto quantize = [](const std::vector<float>& v, float scale, auto type) {
        std::vector<decltype(type)> q;
        for (float x : v) q.push_back(decltype(type)(std::lround(x * scale)));
        return q;
    };
    json sphere_p = {{"attributes",
                      {{"POSITION", w.data(quantize(ball.p, 1000.0f, std::int16_t()), kShort, "VEC3", false, true)},
                       {"NORMAL", w.data(quantize(ball.n, 127.0f, std::int8_t()), kByte, "VEC3", true)},
                       {"TEXCOORD_0", w.data(quantize(ball.uv, 65535.0f, std::uint16_t()), kUShort, "VEC2", true)}}},
                     {"indices", w.data(ball.index, kUShort, "SCALAR")},
                     {"material", textured}};
    // The ring's positions in [-1, 1] as normalized bytes (its node scales them back), its normals
    // normalized shorts, vertex colours normalized unsigned shorts.
    std::vector<float> ring_p;
    for (float x : ring.p) ring_p.push_back(x / 1.0f);
    std::vector<std::uint16_t> colours;
    for (std::size_t i = 0; i < ring.vertices(); ++i) {
        for (const float c : {ring.uv[2 * i], 1.0f - ring.uv[2 * i + 1], 0.4f, 1.0f}) {
            colours.push_back(std::uint16_t(std::lround(c * 65535.0f)));
        }
    }
    json ring_prim = {{"attributes",
                       {{"POSITION", w.data(quantize(ring_p, 127.0f, std::int8_t()), kByte, "VEC3", true, true)},
                        {"NORMAL", w.data(quantize(ring.n, 32767.0f, std::int16_t()), kShort, "VEC3", true)},
                        {"COLOR_0", w.data(colours, kUShort, "VEC4", true)}}},
                      {"indices", w.data(ring.index, kUShort, "SCALAR")},
                      {"material", white}};
    std::vector<int> roots;
    roots.push_back(node(w, "Sphere", mesh(w, "Sphere", json::array({sphere_p})),
                         trs({-1.1f, 0, 0}, about(20, {0, 1, 0}), glm::vec3(0.001f))));
    roots.push_back(node(w, "Ring", mesh(w, "Ring", json::array({ring_prim})),
                         trs({1.1f, 0, 0}, about(65, {1, 0, 0}), glm::vec3(1.0f))));
    roots.push_back(camera(w, "Camera", {0.0f, 0.5f, 5.0f}, {0, 0, 0}, perspective(0.65, 1.0, 20.0)));
    scene(w, roots, 160, 120);
    w.write(dir / "quantized.gltf");
}

// Cameras: a perspective one with an aspect ratio, an orthographic one, and one without an
// aspect ratio, chosen by --camera; rendered at sizes wider and narrower than each.
void cameras(const std::filesystem::path& dir) {
    GltfWriter w;
    const int grid = texture(w, "textures/grid.png", kLinear, kTrilinear);
    const int floor = material(w, "Floor", {{"baseColorTexture", {{"index", grid}}}});
    const int red = material(w, "Red", factor(0.8, 0.2, 0.15));
    std::vector<int> roots;
    roots.push_back(node(w, "Floor", mesh(w, "Floor", json::array({primitive(w, square(), floor)})),
                         trs({0, -1, 0}, about(-90, {1, 0, 0}), {3, 2, 1})));
    const int cube = mesh(w, "Cube", json::array({primitive(w, box(), red)}));
    for (int i = 0; i < 3; ++i) {
        roots.push_back(node(w, "Cube " + std::to_string(i), cube,
                             trs({-2.0f + 2.0f * float(i), -0.5f, 0.3f * float(i)}, about(20.0f * float(i), {0, 1, 0}),
                                 glm::vec3(0.5f))));
    }
    roots.push_back(camera(w, "Wide", {0, 1.5f, 6}, {0, -0.5f, 0}, perspective(0.6, 1.0, 20.0, 2.0)));
    roots.push_back(camera(
        w, "Top", {0, 5, 0.01f}, {0, 0, 0},
        {{"type", "orthographic"}, {"orthographic", {{"xmag", 3.2}, {"ymag", 1.6}, {"znear", 1.0}, {"zfar", 10.0}}}}));
    roots.push_back(camera(w, "Close", {1.5f, 0.5f, 3.0f}, {0, -0.5f, 0}, perspective(0.9, 0.5, 20.0)));
    w["cameras"][1]["name"] = "Top view";
    scene(w, roots, 160, 120);
    w.write(dir / "cameras.gltf");
}

// A modelling tool's export: named nodes with translation, rotation and scale, an interleaved
// vertex buffer (POSITION, NORMAL, TEXCOORD_0 in one strided view), several materials, some
// textured (a file beside the scene), a blended one, an extension used that quadshade does not
// implement, and the camera under a rotated parent.
void workshop(const std::filesystem::path& dir) {
    GltfWriter w;
    w.use_extension("KHR_materials_emissive_strength");
    w.use_extension("KHR_texture_transform");
    const int wood_texture = texture(w, "textures/wood.png", kLinear, kTrilinear);
    const int checker = texture(w, "textures/checker.png", kLinear, kTrilinear);
    const int wood =
        material(w, "Wood",
                 {{"baseColorTexture", {{"index", wood_texture}}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.6}});
    const int cover = material(w, "Cover", {{"baseColorFactor", {0.6, 0.08, 0.06, 1.0}}, {"metallicFactor", 0.0}});
    const int cover_blue =
        material(w, "Cover.001", {{"baseColorFactor", {0.08, 0.2, 0.55, 1.0}}, {"metallicFactor", 0.0}});
    const int ceramic = material(w, "Ceramic", {{"baseColorFactor", {0.92, 0.9, 0.85, 1.0}}, {"roughnessFactor", 0.2}});
    const int brass = material(w, "Brass", {{"baseColorFactor", {0.8, 0.6, 0.25, 1.0}}, {"metallicFactor", 1.0}},
                               {{"emissiveFactor", {1.0, 0.9, 0.6}},
                                {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 2.0}}}}}});
    const int glass = material(w, "Glass", {{"baseColorFactor", {0.75, 0.9, 0.95, 0.3}}, {"roughnessFactor", 0.05}},
                               {{"alphaMode", "BLEND"}});
    const int cloth =
        material(w, "Cloth",
                 {{"baseColorTexture",
                   {{"index", checker}, {"extensions", {{"KHR_texture_transform", {{"scale", {3.0, 3.0}}}}}}}},
                  {"baseColorFactor", {0.9, 0.9, 1.0, 1.0}}});
    // Interleaved: position, normal and texture coordinates of a vertex together, 32 bytes.
    auto interleaved = [&](const Geometry& g, int m) {
        std::vector<float> v;
        for (std::size_t i = 0; i < g.vertices(); ++i) {
            v.insert(v.end(), {g.p[3 * i], g.p[3 * i + 1], g.p[3 * i + 2], g.n[3 * i], g.n[3 * i + 1], g.n[3 * i + 2],
                               g.uv[2 * i], g.uv[2 * i + 1]});
        }
        std::vector<double> lo(3, 1e300), hi(3, -1e300);
        for (std::size_t i = 0; i < g.p.size(); ++i) {
            lo[i % 3] = std::min(lo[i % 3], double(g.p[i])), hi[i % 3] = std::max(hi[i % 3], double(g.p[i]));
        }
        const int view = w.view(v.data(), v.size() * sizeof(float), 32);
        json a = {{"POSITION", w.accessor(view, kFloatType, g.vertices(), "VEC3", false, 0, lo, hi)},
                  {"NORMAL", w.accessor(view, kFloatType, g.vertices(), "VEC3", false, 12)},
                  {"TEXCOORD_0", w.accessor(view, kFloatType, g.vertices(), "VEC2", false, 24)}};
        return json{{"attributes", a}, {"indices", w.data(g.index, kUShort, "SCALAR")}, {"material", m}};
    };
    const Geometry cube = box(), can = cylinder(24), ball = sphere(12, 20), plate = square();
    std::vector<int> roots;
    roots.push_back(node(w, "Table", mesh(w, "Cube", json::array({interleaved(cube, wood)})),
                         trs({0, -0.15f, 0}, kNoRotation, {2.2f, 0.1f, 1.3f})));
    roots.push_back(node(w, "Tablecloth", mesh(w, "Plane", json::array({interleaved(plate, cloth)})),
                         trs({0.9f, -0.04f, 0.3f}, about(-90, {1, 0, 0}) * about(12, {0, 0, 1}), {0.8f, 0.6f, 1})));
    const int book = mesh(w, "Cube.001", json::array({interleaved(cube, cover)}));
    const int book_blue = mesh(w, "Cube.002", json::array({interleaved(cube, cover_blue)}));
    roots.push_back(node(w, "Book", book, trs({-1.2f, 0.05f, 0.2f}, about(15, {0, 1, 0}), {0.45f, 0.1f, 0.32f})));
    roots.push_back(node(w, "Book.001", book, trs({-1.15f, 0.25f, 0.15f}, about(-8, {0, 1, 0}), {0.42f, 0.1f, 0.3f})));
    roots.push_back(
        node(w, "Book.002", book_blue, trs({-1.2f, 0.45f, 0.22f}, about(25, {0, 1, 0}), {0.4f, 0.1f, 0.29f})));
    roots.push_back(node(w, "Cup", mesh(w, "Cylinder", json::array({interleaved(can, ceramic)})),
                         trs({0.3f, 0.2f, -0.3f}, kNoRotation, {0.22f, 0.25f, 0.22f})));
    const int lamp_head = node(w, "Lamp.Head", mesh(w, "Sphere", json::array({interleaved(ball, brass)})),
                               trs({0, 1.1f, 0}, kNoRotation, glm::vec3(0.25f)));
    roots.push_back(node(w, "Lamp", mesh(w, "Cylinder.001", json::array({interleaved(can, brass)})),
                         trs({1.5f, 0.45f, -0.6f}, kNoRotation, {0.05f, 0.5f, 0.05f}), {}));
    w["nodes"][std::size_t(roots.back())]["children"] = {lamp_head};
    // The head under a scaled parent: undo the stem's scale.
    w["nodes"][std::size_t(lamp_head)]["scale"] = {5.0, 0.5, 5.0};
    w["nodes"][std::size_t(lamp_head)]["translation"] = {0.0, 1.2, 0.0};
    roots.push_back(node(w, "Vase", mesh(w, "Sphere.001", json::array({interleaved(ball, glass)})),
                         trs({0.6f, 0.3f, 0.4f}, kNoRotation, {0.28f, 0.35f, 0.28f})));
    // The camera on a turntable: under a parent turned about the vertical.
    const glm::quat turn = about(35, {0, 1, 0});
    const int cam =
        camera(w, "Camera", {2.6f, 2.2f, 3.6f}, {0, 0.1f, 0}, perspective(0.55, 0.1, 100.0, 1.3333333333), turn);
    roots.push_back(node(w, "Turntable", -1, trs({0, 0, 0}, turn), {cam}));
    scene(w, roots, 256, 192, {0.05f, 0.05f, 0.07f, 0.0f});
    w.write(dir / "workshop.gltf");
}

// A CAD assembly as a CAD exporter writes it, in a .glb: a hierarchy of matrices, parts sharing
// meshes, a mirrored half (a negative scale: its faces wind the other way), materials that are
// factors only, no texture coordinates, parts without normals (drawn flat), 32-bit indices, a
// primitive without a material, and no camera (the default camera frames it).
void assembly(const std::filesystem::path& dir) {
    GltfWriter w;
    const int steel = material(w, "Steel", factor(0.55, 0.56, 0.6));
    const int paint = material(w, "Painted", factor(0.12, 0.32, 0.7));
    const int rubber = material(w, "Rubber", factor(0.06, 0.06, 0.06));
    auto part = [&](const Geometry& g, int m, bool normals) {
        std::vector<std::uint32_t> index(g.index.begin(), g.index.end());
        json p = {{"attributes", attributes(w, g, normals, false)}, {"indices", w.data(index, kUInt, "SCALAR")}};
        if (m >= 0) p["material"] = m;
        return p;
    };
    const Geometry plate = box(), bolt = cylinder(12), wheel = torus(0.8f, 0.35f, 28, 12);
    const int plate_mesh = mesh(w, "PLATE-001", json::array({part(plate, paint, false)}));
    const int bolt_mesh = mesh(w, "BOLT-M6", json::array({part(bolt, steel, true), part(box(), -1, false)}));
    const int wheel_mesh = mesh(w, "WHEEL", json::array({part(wheel, rubber, true)}));
    auto matrix = [](const glm::mat4& m) {
        return json{{"matrix", std::vector<float>(glm::value_ptr(m), glm::value_ptr(m) + 16)}};
    };
    // One half: a plate, four bolts and a wheel; the other half is its mirror image.
    auto half = [&](const std::string& name, float side) {
        std::vector<int> children;
        children.push_back(node(w, name + "/PLATE", plate_mesh,
                                matrix(glm::scale(glm::translate(glm::mat4(1), {0, 0, 1.05f}), {1.6f, 0.08f, 1.0f}))));
        for (int i = 0; i < 4; ++i) {
            const float x = (i % 2 ? 1.3f : -1.3f), z = 1.05f + (i / 2 ? 0.7f : -0.7f);
            glm::mat4 m = glm::translate(glm::mat4(1), {x, 0.15f, z});
            m = glm::scale(m, {0.09f, 0.18f, 0.09f});
            children.push_back(node(w, name + "/BOLT-" + std::to_string(i + 1), bolt_mesh, matrix(m)));
        }
        glm::mat4 wm = glm::translate(glm::mat4(1), {1.0f, -0.5f, 2.2f});
        wm = glm::rotate(wm, glm::radians(90.0f), {1, 0, 0});
        wm = glm::scale(wm, glm::vec3(0.45f));
        children.push_back(node(w, name + "/WHEEL", wheel_mesh, matrix(wm)));
        return node(w, name, -1, matrix(glm::scale(glm::mat4(1), {1, 1, side})), children);
    };
    const int left = half("LEFT", 1.0f), right = half("RIGHT (mirrored)", -1.0f);
    glm::mat4 top = glm::rotate(glm::mat4(1), glm::radians(-30.0f), {0, 1, 0});
    top = glm::rotate(top, glm::radians(20.0f), {1, 0, 0});
    const int root = node(w, "ASSEMBLY", -1, matrix(top), {left, right});
    scene(w, {root}, 224, 160, {0.9f, 0.9f, 0.92f, 0.0f});
    w.write(dir / "assembly.glb");
}

}  // namespace

void write_gltf_scenes(const std::filesystem::path& dir) {
    const std::filesystem::path out = dir / "gltf";
    std::filesystem::create_directories(out / "textures");
    write_image(out / "textures" / "checker.png", checker_image());
    write_image(out / "textures" / "leaf.png", leaf_image());
    write_image(out / "textures" / "grid.png", grid_image());
    write_image(out / "textures" / "wood.png", wood_image());
    default_material(out);
    alpha_modes(out);
    texcoord_sets(out);
    primitive_modes(out);
    animation(out);
    instancing(out);
    quantized(out);
    cameras(out);
    workshop(out);
    assembly(out);
}

}  // namespace qs
