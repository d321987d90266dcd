#pragma once
// A cube map for tests: six faces of hashed texels over smooth ramps, each face its own pattern,
// written as PNG files.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "images/image_io.h"
#include "scenes/scene.h"

namespace qs::test {

// Six square faces of `size` texels written to `dir` (face0.png .. face5.png, +X to -Z) and the
// scene texture of them (with `compare`: a depth comparison cube map, whose depth is each face's
// red, compared by that function).
inline Texture cube_map(const std::filesystem::path& dir, int size, const Sampler& sampler,
                        std::optional<CompareFunc> compare, const std::string& field) {
    Texture t;
    t.dims = kCubeMap;
    t.sampler = sampler;
    t.compare = compare;
    t.field = field;
    for (int f = 0; f < 6; ++f) {
        Image8 image;
        image.width = image.height = size;
        image.rgba.resize(std::size_t(size) * std::size_t(size) * 4);
        for (int y = 0; y < size; ++y) {
            for (int x = 0; x < size; ++x) {
                std::uint32_t h = std::uint32_t(x) * 73856093u ^ std::uint32_t(y) * 19349663u ^ std::uint32_t(f + 1) * 83492791u;
                h ^= h >> 13, h *= 0x5bd1e995u, h ^= h >> 15;
                std::uint8_t* px = &image.rgba[(std::size_t(y) * std::size_t(size) + std::size_t(x)) * 4];
                // ramps under the hash, so that each face and each level reads differently
                px[0] = std::uint8_t((x * 255 / size + int(h & 63)) & 255);
                px[1] = std::uint8_t((y * 255 / size + int((h >> 8) & 63)) & 255);
                px[2] = std::uint8_t(f * 40 + int((h >> 16) & 31));
                px[3] = 255;
            }
        }
        const std::filesystem::path file = dir / (field + "-face" + std::to_string(f) + ".png");
        write_image(file, image);
        ImageSource face;
        face.file = file;
        t.faces.push_back(face);
    }
    return t;
}

}  // namespace qs::test
