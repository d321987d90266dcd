#include "render/gallery.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "scenes/gltf.h"
#include "shading/catalogue.h"

namespace qs {

namespace {

constexpr float kBackground = 0.12f;  // the sheet's grey
constexpr float kUndrawn = 0.3f;      // a square no scene could feed
constexpr int kTitle = 30;            // pixels above the squares for the collection's name

// The scene `info` is drawn on: the first that binds its textures, a solids scene first for a
// solid texture. -1: none.
int scene_for(const ShaderInfo& info, const std::vector<Scene>& scenes, const std::vector<std::filesystem::path>& files) {
    if (info.needs.coordinates == Coordinates::Object3D) {
        for (std::size_t i = 0; i < scenes.size(); ++i) {
            if (files[i].stem().string().find("solids") != std::string::npos && binds_samplers(scenes[i], info)) return int(i);
        }
    }
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        if (binds_samplers(scenes[i], info)) return int(i);
    }
    return -1;
}

void fill(Image& image, int x0, int y0, int w, int h, float grey) {
    for (int y = y0; y < y0 + h; ++y) {
        for (int x = x0; x < x0 + w; ++x) {
            float* p = &image.rgba[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4];
            p[0] = p[1] = p[2] = grey, p[3] = 1.0f;
        }
    }
}

}  // namespace

std::string gallery_file_stem(const std::string& collection) {
    std::string stem;
    for (char c : collection.substr(0, collection.find(':'))) {
        if (std::isalnum((unsigned char)c)) stem += char(std::tolower((unsigned char)c));
        else if ((c == ' ' || c == '-' || c == '_' || c == '.' || c == '/') && !stem.empty() && stem.back() != '-') stem += '-';
    }
    while (!stem.empty() && stem.back() == '-') stem.pop_back();
    return stem.empty() ? std::string("collection") : stem;
}

std::vector<GallerySheet> render_gallery(const GalleryRequest& request) {
    if (request.tile < 16 || request.tile > 1024) {
        throw std::invalid_argument("gallery squares of " + std::to_string(request.tile) + " pixels: expected 16 to 1024");
    }
    if (request.scenes.empty()) throw std::invalid_argument("the gallery has no scene to draw on");
    std::vector<Scene> scenes;
    for (const std::filesystem::path& f : request.scenes) scenes.push_back(load_scene(f));

    const int tile = request.tile, label = std::max(10, tile / 12), strip = label + 8;
    std::vector<GallerySheet> sheets;
    for (const auto& [collection, programs] : catalogue_by_collection()) {
        const auto& only = request.collections;
        if (!only.empty() && std::find(only.begin(), only.end(), collection) == only.end()) continue;
        GallerySheet sheet{collection, {}, {}};
        const int n = int(programs.size()), columns = std::clamp(request.columns, 1, n), rows = (n + columns - 1) / columns;
        Image& image = sheet.image;
        image.width = columns * tile, image.height = kTitle + rows * (tile + strip);
        image.rgba.assign(std::size_t(image.width) * std::size_t(image.height) * 4, 0.0f);
        fill(image, 0, 0, image.width, image.height, kBackground);
        draw_text(image, 6, 21, collection, 16);
        for (int k = 0; k < n; ++k) {
            const ShaderInfo& info = programs[std::size_t(k)]->info();
            const int x0 = (k % columns) * tile, y0 = kTitle + (k / columns) * (tile + strip);
            const int s = scene_for(info, scenes, request.scenes);
            std::string name(info.name);
            if (s < 0) {
                fill(image, x0, y0, tile, tile, kUndrawn);
                sheet.drawn.emplace_back(name, std::filesystem::path());
                name += " (no scene binds its textures)";
            } else {
                FrameRequest frame = request.frame;
                frame.width = frame.height = tile;
                frame.shader_override = info.name;
                const Framebuffer fb = render_frame(scenes[std::size_t(s)], frame);
                for (int y = 0; y < tile; ++y) {
                    std::copy_n(&fb.rgba[std::size_t(y) * std::size_t(tile) * 4], std::size_t(tile) * 4,
                                &image.rgba[(std::size_t(y0 + y) * std::size_t(image.width) + std::size_t(x0)) * 4]);
                }
                sheet.drawn.emplace_back(name, request.scenes[std::size_t(s)]);
            }
            draw_text(image, x0 + 4, y0 + tile + label + 2, name, label);
        }
        // Alpha is coverage in a frame; a sheet is opaque.
        for (std::size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 1.0f;
        sheets.push_back(std::move(sheet));
    }
    return sheets;
}

}  // namespace qs
