#include "generators/gltf_writer.h"

#include <algorithm>
#include <fstream>
#include <stdexcept>

namespace qs {

GltfWriter::GltfWriter() { doc_["asset"] = {{"version", "2.0"}, {"generator", "quadshade scene generator"}}; }

int GltfWriter::components(const std::string& type) {
    if (type == "SCALAR") return 1;
    if (type == "VEC2") return 2;
    if (type == "VEC3") return 3;
    if (type == "VEC4") return 4;
    if (type == "MAT4") return 16;
    throw std::invalid_argument("GltfWriter: unknown accessor type " + type);
}

int GltfWriter::view(const void* data, std::size_t bytes, int stride) {
    while (bin_.size() % 4) bin_.push_back(0);
    json v = {{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", bytes}};
    if (stride) v["byteStride"] = stride;
    const auto* p = static_cast<const unsigned char*>(data);
    bin_.insert(bin_.end(), p, p + bytes);
    return add("bufferViews", v);
}

int GltfWriter::accessor(int view, int component_type, std::size_t count, const std::string& type, bool normalized,
                         std::size_t offset, const std::vector<double>& min, const std::vector<double>& max) {
    json a = {{"bufferView", view}, {"componentType", component_type}, {"count", count}, {"type", type}};
    if (offset) a["byteOffset"] = offset;
    if (normalized) a["normalized"] = true;
    if (!min.empty()) a["min"] = min, a["max"] = max;
    return add("accessors", a);
}

int GltfWriter::add(const std::string& array, json value) {
    json& list = doc_[array];
    if (list.is_null()) list = json::array();
    list.push_back(std::move(value));
    return int(list.size() - 1);
}

void GltfWriter::use_extension(const std::string& name, bool required) {
    for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
        if (std::string(key) == "extensionsRequired" && !required) continue;
        json& list = doc_[key];
        if (list.is_null()) list = json::array();
        if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
    }
}

void GltfWriter::write(const std::filesystem::path& path) {
    while (bin_.size() % 4) bin_.push_back(0);
    const bool binary = path.extension() == ".glb";
    json doc = doc_;
    doc["buffers"] = json::array({{{"byteLength", bin_.size()}}});
    if (!binary) doc["buffers"][0]["uri"] = path.stem().string() + ".bin";
    std::string text = doc.dump(1);
    std::ofstream out(path, std::ios::binary);
    if (binary) {
        while (text.size() % 4) text += ' ';
        auto word = [&](std::uint32_t v) { out.write(reinterpret_cast<const char*>(&v), 4); };
        word(0x46546C67), word(2), word(std::uint32_t(12 + 8 + text.size() + 8 + bin_.size()));
        word(std::uint32_t(text.size())), word(0x4E4F534A);
        out.write(text.data(), std::streamsize(text.size()));
        word(std::uint32_t(bin_.size())), word(0x004E4942);
    } else {
        out << text << '\n';
        std::ofstream bin(path.parent_path() / (path.stem().string() + ".bin"), std::ios::binary);
        bin.write(reinterpret_cast<const char*>(bin_.data()), std::streamsize(bin_.size()));
        if (!bin) throw std::runtime_error(path.string() + ": cannot write its .bin");
    }
    out.write(reinterpret_cast<const char*>(bin_.data()), binary ? std::streamsize(bin_.size()) : 0);
    if (!out) throw std::runtime_error(path.string() + ": cannot write");
}

}  // namespace qs
