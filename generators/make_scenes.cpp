// Generates the scenes quadshade ships (scenes/assets): the Figure 1.1 scene, the solid textures'
// sphere, the Table 1.1 plane and its texture, the ProcTexGen spheres and the fast noise's volume,
// Lawlor's plane and its noise texture, the solids (sphere and torus), the conformance scenes
// (geometry_scenes.h, texture_scenes.h) and the meshes with UV atlases for `quadshade bake`
// (atlas_scenes.h). The outputs are committed; a test regenerates them and compares.
//
//   quadshade-make-scenes OUTPUT_DIR

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include "generators/atlas_scenes.h"
#include "generators/geometry_scenes.h"
#include "generators/gltf_scenes.h"
#include "generators/texture_scenes.h"
#include "images/image_io.h"
#include "scenes/gltf.h"
#include "scenes/scene.h"
#include "shading/noise/improved_noise.h"

namespace {

using qs::Mesh;

// The chapter's sphere: radius 1, poles on +-z, 20 latitude bands, 40 longitude steps with the
// seam vertex duplicated; a fan at each pole, 18 strips between: 1520 triangles.
Mesh sphere_mesh() {
    constexpr int bands = 20, steps = 40;
    Mesh m;
    m.name = "sphere";
    auto vertex = [&](int band, int step) {
        const double theta = std::numbers::pi * band / bands;  // from the +z pole
        const double phi = 2.0 * std::numbers::pi * step / steps;
        m.vertices.push_back({{float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                               float(std::cos(theta))},
                              {float(step) / steps, 1.0f - float(band) / bands}});
    };
    vertex(0, 0);  // north pole
    for (int band = 1; band < bands; ++band) {
        for (int step = 0; step <= steps; ++step) vertex(band, step);
    }
    vertex(bands, 0);  // south pole
    const auto ring = [&](int band, int step) { return std::uint32_t(1 + (band - 1) * (steps + 1) + step); };
    const std::uint32_t south = std::uint32_t(m.vertices.size() - 1);
    for (int s = 0; s < steps; ++s) m.indices.insert(m.indices.end(), {0, ring(1, s), ring(1, s + 1)});
    for (int band = 1; band < bands - 1; ++band) {
        for (int s = 0; s < steps; ++s) {
            m.indices.insert(m.indices.end(), {ring(band, s), ring(band + 1, s), ring(band, s + 1)});
            m.indices.insert(m.indices.end(), {ring(band, s + 1), ring(band + 1, s), ring(band + 1, s + 1)});
        }
    }
    for (int s = 0; s < steps; ++s) m.indices.insert(m.indices.end(), {ring(bands - 1, s), south, ring(bands - 1, s + 1)});
    return m;
}

// A square (-1,-1,0)..(1,1,0) of two triangles, st = (0,0)..(1,1).
Mesh square_mesh() {
    Mesh m;
    m.name = "square";
    m.vertices = {{{-1, -1, 0}, {0, 0}}, {{1, -1, 0}, {1, 0}}, {{1, 1, 0}, {1, 1}}, {{-1, 1, 0}, {0, 1}}};
    m.indices = {0, 1, 2, 0, 2, 3};
    return m;
}

qs::Object object(std::string name, std::size_t mesh, const glm::mat4& world_from_object, std::string shader) {
    qs::Object o;
    o.name = std::move(name), o.mesh = mesh, o.world_from_object = world_from_object, o.shader = std::move(shader);
    return o;
}

qs::Scene figure_1_1() {
    qs::Scene s;
    s.meshes = {square_mesh(), sphere_mesh()};
    s.camera.yfov = glm::radians(15.0f);
    s.camera.znear = 1.0f, s.camera.zfar = 100.0f;
    s.camera.view = glm::lookAt(glm::vec3(0, -8, 1), glm::vec3(0, 0, -0.5f), glm::vec3(0, 0, 1));
    s.clear_color = {0.0f, 0.3f, 0.5f, 0.0f};
    s.time = 1.0f;
    s.width = 1264, s.height = 400;
    const glm::mat4 plane = glm::scale(glm::translate(glm::mat4(1), {0, 3, -1.5f}), {4, 4, 1});
    s.objects.push_back(object("ground plane", 0, plane, "flow_noise"));
    const char* shaders[4] = {"simplex3d", "turbulence", "spots", "tiles3d"};
    const float xs[4] = {-1.8f, -0.6f, 0.6f, 1.8f};
    for (int i = 0; i < 4; ++i) {
        const glm::mat4 m = glm::scale(glm::translate(glm::mat4(1), {xs[i], -2, 0}), glm::vec3(0.5f));
        s.objects.push_back(object("sphere " + std::to_string(i + 1), 1, m, shaders[i]));
    }
    return s;
}

// The solid textures' scene: the chapter's sphere alone, seen from above its equator in
// perspective, so that its silhouette, its poles' fans and the seam's helper lanes are all in
// view. The OSMesa tests draw every solid texture of the catalogue on it.
qs::Scene sphere() {
    qs::Scene s;
    s.meshes = {sphere_mesh()};
    s.camera.yfov = glm::radians(34.0f);
    s.camera.znear = 1.0f, s.camera.zfar = 10.0f;
    s.camera.view = glm::lookAt(glm::vec3(2.2f, -2.6f, 1.6f), glm::vec3(0.0f), glm::vec3(0, 0, 1));
    s.clear_color = {0.0f, 0.3f, 0.5f, 0.0f};
    s.time = 1.0f;
    s.width = 320, s.height = 320;
    s.objects.push_back(object("sphere", 0, glm::mat4(1.0f), "simplex3d_fibonacci"));
    return s;
}

qs::Scene table_1_1_plane(const std::filesystem::path& dir) {
    qs::Scene s;
    s.meshes = {square_mesh()};
    // Orthographic camera at z = 1 looking down -z: the square fills the window exactly, at any size.
    s.camera.kind = qs::Camera::Kind::Orthographic;
    s.camera.xmag = 1.0f, s.camera.ymag = 1.0f, s.camera.znear = 0.5f, s.camera.zfar = 1.5f;
    s.camera.stretch = true;  // the plane fills any window, as the chapter's demo draws it
    s.camera.view = glm::translate(glm::mat4(1), {0, 0, -1});
    s.clear_color = {0, 0, 0, 1};
    s.width = 500, s.height = 500;
    // The texture of the Table 1.1 benchmark: bilinear, clamped, no mipmaps.
    qs::Texture texture;
    texture.image.file = dir / "textures" / "halftone-source.png";
    texture.sampler = {qs::Filter::Linear, qs::Filter::Linear, qs::Wrap::ClampToEdge, qs::Wrap::ClampToEdge};
    s.textures.push_back(texture);
    qs::Object o = object("plane", 0, glm::mat4(1), "perlin");
    o.texture = 0;
    s.objects.push_back(o);
    return s;
}

// A 256x256 colour image for the texture shaders: smooth hues, a grey ramp and a few discs, so
// that the halftone screens show every ink. The plane's st has t = 0 at the bottom of the window
// (the book's gl_MultiTexCoord0), and glTF puts t = 0 at an image's first row: so the picture is
// stored bottom row first, and shows upright on the plane (the grey ramp along its bottom edge).
qs::Image test_image() {
    constexpr int n = 256;
    qs::Image img{n, n, std::vector<float>(std::size_t(n) * n * 4)};
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            const double u = (x + 0.5) / n, v = (n - 1 - y + 0.5) / n;  // v down the picture as shown
            double r = 0.5 + 0.5 * std::cos(2 * std::numbers::pi * (u + 0.0));
            double g = 0.5 + 0.5 * std::cos(2 * std::numbers::pi * (u + v * 0.5 + 0.33));
            double b = 0.5 + 0.5 * std::cos(2 * std::numbers::pi * (v + 0.66));
            if (v > 0.85) r = g = b = u;  // grey ramp
            const double cx[3] = {0.3, 0.65, 0.5}, cy[3] = {0.35, 0.5, 0.7}, rad[3] = {0.12, 0.09, 0.06};
            for (int i = 0; i < 3; ++i) {
                if (std::hypot(u - cx[i], v - cy[i]) < rad[i]) r = (i == 0), g = (i == 1), b = (i == 2) ? 0.2 : 0.9;
            }
            float* p = &img.rgba[(std::size_t(y) * n + std::size_t(x)) * 4];
            p[0] = float(r), p[1] = float(g), p[2] = float(b), p[3] = 1.0f;
        }
    }
    return img;
}

// Lawlor's tex4, which his notes leave to NetRun ("this looks better with a noisy repeating
// image"): 32x32 white noise, each of red, green and blue a byte of the PCG hash of the texel and
// channel, opaque (so that every pixel of a shader that returns the texture counts as covered).
qs::Image8 white_noise_image() {
    constexpr int n = 32;
    auto pcg_hash = [](std::uint32_t v) {
        const std::uint32_t state = v * 747796405u + 2891336453u;
        const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
        return (word >> 22u) ^ word;
    };
    qs::Image8 img{n, n, std::vector<std::uint8_t>(std::size_t(n) * n * 4)};
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            std::uint8_t* p = &img.rgba[(std::size_t(y) * n + std::size_t(x)) * 4];
            for (int c = 0; c < 3; ++c) p[c] = std::uint8_t(pcg_hash(std::uint32_t((c * n + y) * n + x)) >> 24);
            p[3] = 255;
        }
    }
    return img;
}

// The solid textures' scene: the chapter's sphere beside a torus (non-convex, its far side
// occluded by its near side through the hole), both within [-1, 1]^3 in object space as the
// solid textures' vertex stages expect, under a perspective camera; square (512x512), as the
// gallery draws it.
qs::Scene solids() {
    qs::Scene s;
    s.meshes = {sphere_mesh(), qs::torus_mesh(0.68f, 0.3f, 72, 28, 6.0f, 2.0f)};
    s.camera.yfov = glm::radians(48.0f);
    s.camera.znear = 1.0f, s.camera.zfar = 20.0f;
    s.camera.view = glm::lookAt(glm::vec3(0, -5.2f, 1.6f), glm::vec3(0, 0, 0), glm::vec3(0, 0, 1));
    s.clear_color = {0.0f, 0.3f, 0.5f, 0.0f};
    s.time = 1.0f;
    s.width = 512, s.height = 512;
    const glm::mat4 I(1.0f);
    s.objects.push_back(object("sphere", 0, glm::translate(I, {-1.15f, 0, 0}), "simplex3d"));
    // The torus lies around y: tilted towards the camera so that its hole shows.
    s.objects.push_back(object("torus", 1, glm::rotate(glm::translate(I, {1.15f, 0, 0}), glm::radians(-60.0f), {1, 0, 0}), "spots"));
    return s;
}

// Lawlor's plane: the Table 1.1 plane, its texture coordinates NetRun's `texcoords`, with the
// two textures the snippets read: tex1 the Table 1.1 picture (smooth colours) and tex4 the white
// noise, both repeating (the snippets read them far outside [0, 1]), bilinear, no mipmaps.
qs::Scene lawlor_plane(const std::filesystem::path& dir) {
    qs::Scene s = table_1_1_plane(dir);
    const qs::Sampler repeat{qs::Filter::Linear, qs::Filter::Linear, qs::Wrap::Repeat, qs::Wrap::Repeat};
    s.textures[0].sampler = repeat;
    qs::Texture noise;
    noise.image.file = dir / "textures" / "lawlor-noise.png";
    noise.sampler = repeat;
    s.textures.push_back(noise);
    qs::Object& o = s.objects[0];
    o.shader = "lawlor_voronoi_f1";
    o.texture = -1;
    o.samplers = {{"tex1", 0}, {"tex4", 1}};
    return s;
}

// The ProcTexGen articles' fast noise volume (shading/shaders/fast_noise_volume.frag): 32^3 texels of 8^3-cell
// looping improved noise, R base 0 and G base 8, stored 0.5 + 0.5 n in 8 bits, as GL stores the
// shader's colour (clamp, scale by 255, round to nearest). Texel (i, j, k) is the noise at P = 8
// ((i, j, k) + 0.5) / 32, exact in float: the values `quadshade bake-volume --shader
// fast_noise_volume --size 32` renders at its texel centres (a test compares the two, and the
// bake with OSMesa's), computed here from the noise itself so that the file does not depend on
// the rasterizer's interpolation. Slice k is rows [32 k, 32 k + 32), row j is y texel j.
qs::Image8 fast_noise_volume() {
    constexpr int n = 32;
    auto unorm8 = [](float v) { return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
    qs::Image8 img{n, n * n, std::vector<std::uint8_t>(std::size_t(n) * n * n * 4)};
    for (int k = 0; k < n; ++k) {
        for (int j = 0; j < n; ++j) {
            for (int i = 0; i < n; ++i) {
                const qs::glsl::vec3<float> P(8.0f * (float(i) + 0.5f) / 32.0f, 8.0f * (float(j) + 0.5f) / 32.0f,
                                              8.0f * (float(k) + 0.5f) / 32.0f);
                std::uint8_t* p = &img.rgba[((std::size_t(k) * n + std::size_t(j)) * n + std::size_t(i)) * 4];
                p[0] = unorm8(0.5f + 0.5f * qs::noise::texShaderNoise(P, 8, 0));
                p[1] = unorm8(0.5f + 0.5f * qs::noise::texShaderNoise(P, 8, 8));
                p[2] = 0, p[3] = 255;
            }
        }
    }
    return img;
}

// The ProcTexGen articles' solid textures on Figure 1.1's spheres and ground plane: improved noise against the
// fast noise (the blog's comparison, left and right), the looping noise, and the fast noise's
// volume itself; fast_noise reads the volume above (REPEAT, trilinear, no mipmaps: the blog's
// wrapped texcoord).
qs::Scene proctexgen_spheres(const std::filesystem::path& dir) {
    qs::Scene s = figure_1_1();
    qs::Texture volume;
    volume.image.file = dir / "textures" / "fast-noise-volume.png";
    volume.sampler = {qs::Filter::Linear, qs::Filter::Linear, qs::Wrap::Repeat, qs::Wrap::Repeat, qs::Wrap::Repeat};
    volume.dims = 3, volume.depth = 32;
    s.textures.push_back(volume);
    const char* shaders[5] = {"improved_noise_loop", "improved_noise", "fast_noise", "improved_noise_loop", "fast_noise_volume"};
    // Every material binds the volume, so that any of the scene's shaders can be drawn on any
    // object (--shader, quadshade gallery); only fast_noise samples it.
    for (std::size_t i = 0; i < s.objects.size(); ++i) {
        s.objects[i].shader = shaders[i];
        s.objects[i].samplers = {{"noise3dSampler", 0}};
    }
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2 || std::string(argv[1]) == "--help") {
        std::fprintf(stderr, "usage: quadshade-make-scenes OUTPUT_DIR\n"
                             "Writes figure-1.1.gltf, sphere.gltf, table-1.1-plane.gltf, proctexgen-spheres.gltf,\n"
                             "lawlor-plane.gltf, solids.gltf (+ .bin), textures/, conformance/, bake/ and gltf/.\n");
        return argc == 2 ? 0 : 2;
    }
    try {
        const std::filesystem::path dir = argv[1];
        std::filesystem::create_directories(dir / "textures");
        qs::write_image(dir / "textures" / "halftone-source.png", test_image());
        qs::save_scene(figure_1_1(), dir / "figure-1.1.gltf");
        qs::save_scene(sphere(), dir / "sphere.gltf");
        qs::save_scene(table_1_1_plane(dir), dir / "table-1.1-plane.gltf");
        qs::write_image(dir / "textures" / "lawlor-noise.png", white_noise_image());
        qs::save_scene(lawlor_plane(dir), dir / "lawlor-plane.gltf");
        qs::save_scene(solids(), dir / "solids.gltf");
        qs::write_image(dir / "textures" / "fast-noise-volume.png", fast_noise_volume());
        qs::save_scene(proctexgen_spheres(dir), dir / "proctexgen-spheres.gltf");
        qs::write_geometry_scenes(dir);
        qs::write_texture_scenes(dir);
        qs::write_atlas_scenes(dir);
        qs::write_gltf_scenes(dir);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "quadshade-make-scenes: %s\n", e.what());
        return 1;
    }
    return 0;
}
