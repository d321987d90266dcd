#pragma once
// A glTF document written field by field, as exporters write them: for the scene generator's glTF
// feature scenes (gltf_scenes.h), which use what the scene model cannot hold (strips, quantized
// and normalized attributes, interleaved buffers, animations, instancing, extensions).

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace qs {

class GltfWriter {
public:
    using json = nlohmann::json;

    GltfWriter();

    // A buffer view of `bytes` (4-byte aligned in the one buffer), with a byteStride if non-zero.
    int view(const void* data, std::size_t bytes, int stride = 0);
    // An accessor of `count` elements of `type` ("VEC3", ...) in `view` from `offset`; with
    // min and max where given (POSITION needs them).
    int accessor(int view, int component_type, std::size_t count, const std::string& type, bool normalized = false,
                 std::size_t offset = 0, const std::vector<double>& min = {}, const std::vector<double>& max = {});
    // A view and an accessor of tightly packed values at once; `components` per element.
    template <class T>
    int data(const std::vector<T>& values, int component_type, const std::string& type, bool normalized = false,
             bool bounds = false) {
        const int n = components(type);
        std::vector<double> lo, hi;
        if (bounds) {
            lo.assign(std::size_t(n), 1e300), hi.assign(std::size_t(n), -1e300);
            for (std::size_t i = 0; i < values.size(); ++i) {
                const std::size_t c = i % std::size_t(n);
                lo[c] = std::min(lo[c], double(values[i])), hi[c] = std::max(hi[c], double(values[i]));
            }
        }
        return accessor(view(values.data(), values.size() * sizeof(T)), component_type, values.size() / std::size_t(n),
                        type, normalized, 0, lo, hi);
    }
    // An array entry: its index.
    int add(const std::string& array, json value);
    json& operator[](const std::string& key) { return doc_[key]; }
    void use_extension(const std::string& name, bool required = false);

    // Writes `path`: a .gltf with its buffer in a .bin beside it, or a .glb holding both.
    void write(const std::filesystem::path& path);

    static int components(const std::string& type);

private:
    json doc_;
    std::vector<unsigned char> bin_;
};

// glTF's component types.
inline constexpr int kByte = 5120, kUByte = 5121, kShort = 5122, kUShort = 5123, kUInt = 5125, kFloatType = 5126;

}  // namespace qs
