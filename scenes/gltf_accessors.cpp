// glTF's buffers, buffer views and accessors read into packed bytes and floats, every offset,
// stride, count, type and sparse substitution checked before it is used (what tinygltf does not
// check); the component types glTF 2.0 and KHR_mesh_quantization allow each attribute.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <set>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <tiny_gltf.h>

#include "scenes/gltf_checks.h"
#include "scenes/gltf_read.h"
#include "scenes/limits.h"
#include "scenes/scene_files.h"

namespace qs::gltf_read {

namespace checks = gltf_checks;

namespace {

// Bytes [offset, offset + (count - 1) stride + element) of buffer view `view`, checked.
const unsigned char* view_range(const tinygltf::Model& m, int view, std::uint64_t offset, std::uint64_t count,
                                std::uint64_t stride, std::uint64_t element, const std::filesystem::path& file,
                                const std::string& field) {
    if (view < 0 || std::size_t(view) >= m.bufferViews.size()) fail(file, field + ".bufferView", "index out of range");
    const tinygltf::BufferView& v = m.bufferViews[std::size_t(view)];
    const auto end = checks::strided_end(offset, count, stride, element);
    if (!end || *end > v.byteLength) {
        fail(file, field, std::to_string(count) + " elements of " + std::to_string(element) + " bytes, " +
                              std::to_string(stride) + " apart from byte " + std::to_string(offset) +
                              ", reach past the end of bufferViews[" + std::to_string(view) + "] (" +
                              std::to_string(v.byteLength) + " bytes)");
    }
    return m.buffers[std::size_t(v.buffer)].data.data() + v.byteOffset;  // v checked by check_buffer_views
}

bool is_index_type(int component_type) {
    return component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
           component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
           component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

std::string type_name(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return "SCALAR";
        case TINYGLTF_TYPE_VEC2:
            return "VEC2";
        case TINYGLTF_TYPE_VEC3:
            return "VEC3";
        case TINYGLTF_TYPE_VEC4:
            return "VEC4";
        default:
            return "type " + std::to_string(type);
    }
}

std::string component_name(int component_type, bool normalized) {
    std::string n;
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            n = "BYTE";
            break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            n = "UNSIGNED_BYTE";
            break;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            n = "SHORT";
            break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            n = "UNSIGNED_SHORT";
            break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            n = "UNSIGNED_INT";
            break;
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            n = "FLOAT";
            break;
        default:
            n = std::to_string(component_type);
    }
    return normalized ? n + " normalized" : n;
}

}  // namespace

// Buffer views lie inside their buffers and have strides glTF allows; checked once for all,
// before any accessor reads through them.
void check_buffer_views(const tinygltf::Model& m, const std::filesystem::path& file) {
    for (std::size_t i = 0; i < m.bufferViews.size(); ++i) {
        const tinygltf::BufferView& v = m.bufferViews[i];
        const std::string field = indexed("bufferViews", i);
        if (v.buffer < 0 || std::size_t(v.buffer) >= m.buffers.size()) fail(file, field + ".buffer", "index out of range");
        const auto end = checks::checked_add(v.byteOffset, v.byteLength);
        const std::size_t size = m.buffers[std::size_t(v.buffer)].data.size();
        if (!end || *end > size) {
            fail(file, field, "bytes " + std::to_string(v.byteOffset) + " + " + std::to_string(v.byteLength) +
                                  " reach past the end of buffers[" + std::to_string(v.buffer) + "] (" +
                                  std::to_string(size) + " bytes)");
        }
        if (v.byteStride != 0 && (v.byteStride < 4 || v.byteStride > 252 || v.byteStride % 4 != 0)) {
            fail(file, field + ".byteStride", std::to_string(v.byteStride) + " is not a multiple of 4 in 4..252");
        }
    }
}

std::uint32_t read_index(const unsigned char* p, int component_type) {
    if (component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) return *p;
    if (component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
        std::uint16_t s;
        std::memcpy(&s, p, 2);
        return s;
    }
    std::uint32_t v;
    std::memcpy(&v, p, 4);
    return v;
}

AccessorData read_accessor(const tinygltf::Model& m, int index, const std::filesystem::path& file,
                           const std::string& field, int want_type, std::initializer_list<int> want_components,
                           std::uint64_t max_count) {
    if (index < 0 || std::size_t(index) >= m.accessors.size()) fail(file, field, "accessor index out of range");
    const tinygltf::Accessor& a = m.accessors[std::size_t(index)];
    const std::string af = indexed("accessors", std::size_t(index));
    if (a.type != want_type) fail(file, field, af + " has the wrong element type");
    bool component_ok = false;
    for (int c : want_components) component_ok |= a.componentType == c;
    if (!component_ok) fail(file, field, af + " has an unsupported component type " + std::to_string(a.componentType));
    if (a.count > max_count) {
        fail(file, af + ".count", std::to_string(a.count) + " is more than the " + std::to_string(max_count) +
                                      " quadshade accepts");
    }
    AccessorData d;
    d.count = a.count;
    d.component_type = a.componentType;
    d.element = std::size_t(tinygltf::GetComponentSizeInBytes(std::uint32_t(a.componentType))) *
                std::size_t(tinygltf::GetNumComponentsInType(std::uint32_t(a.type)));
    d.bytes.assign(d.count * d.element, 0);  // no buffer view: zeros (sparse data may follow)
    if (a.bufferView >= 0) {
        if (std::size_t(a.bufferView) >= m.bufferViews.size()) fail(file, af + ".bufferView", "index out of range");
        const std::size_t view_stride = m.bufferViews[std::size_t(a.bufferView)].byteStride;
        const std::size_t stride = view_stride ? view_stride : d.element;
        if (stride < d.element) fail(file, af, "byteStride " + std::to_string(stride) + " is less than an element");
        const unsigned char* base = view_range(m, a.bufferView, a.byteOffset, d.count, stride, d.element, file, af);
        for (std::size_t i = 0; i < d.count; ++i) std::memcpy(&d.bytes[i * d.element], base + a.byteOffset + i * stride, d.element);
    }
    if (a.sparse.isSparse) {
        const auto& s = a.sparse;
        const std::string sf = af + ".sparse";
        if (s.count < 1 || std::uint64_t(s.count) > d.count) {
            fail(file, sf + ".count", std::to_string(s.count) + " is not in 1.." + std::to_string(d.count));
        }
        if (!is_index_type(s.indices.componentType)) fail(file, sf + ".indices.componentType", "not an unsigned integer type");
        if (s.indices.byteOffset < 0) fail(file, sf + ".indices.byteOffset", "negative");
        if (s.values.byteOffset < 0) fail(file, sf + ".values.byteOffset", "negative");
        const std::size_t index_size = std::size_t(tinygltf::GetComponentSizeInBytes(std::uint32_t(s.indices.componentType)));
        const unsigned char* indices = view_range(m, s.indices.bufferView, std::uint64_t(s.indices.byteOffset),
                                                  std::uint64_t(s.count), index_size, index_size, file, sf + ".indices");
        const unsigned char* values = view_range(m, s.values.bufferView, std::uint64_t(s.values.byteOffset),
                                                 std::uint64_t(s.count), d.element, d.element, file, sf + ".values");
        indices += s.indices.byteOffset, values += s.values.byteOffset;
        std::int64_t previous = -1;
        for (std::size_t k = 0; k < std::size_t(s.count); ++k) {
            const std::uint32_t i = read_index(indices + k * index_size, s.indices.componentType);
            if (std::int64_t(i) <= previous || i >= d.count) {
                fail(file, sf + ".indices", "index " + std::to_string(i) + " at position " + std::to_string(k) +
                                                " does not increase or is not below count " + std::to_string(d.count));
            }
            previous = i;
            std::memcpy(&d.bytes[i * d.element], values + k * d.element, d.element);
        }
    }
    return d;
}

Floats read_floats(const tinygltf::Model& m, int index, const std::filesystem::path& file, const std::string& field,
                   std::initializer_list<int> want_types, std::initializer_list<Component> want_components,
                   std::uint64_t max_count, const char* element) {
    if (index < 0 || std::size_t(index) >= m.accessors.size()) fail(file, field, "accessor index out of range");
    const tinygltf::Accessor& a = m.accessors[std::size_t(index)];
    const std::string af = indexed("accessors", std::size_t(index));
    if (std::find(want_types.begin(), want_types.end(), a.type) == want_types.end()) {
        std::string types;
        for (int t : want_types) types += (types.empty() ? "" : " or ") + type_name(t);
        fail(file, field, af + " is " + type_name(a.type) + ", expected " + types);
    }
    const bool normalized = a.normalized && a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT;
    bool allowed = false;
    std::string allowed_list;
    for (const Component& c : want_components) {
        allowed |= c.type == a.componentType && c.normalized == normalized;
        allowed_list += (allowed_list.empty() ? "" : ", ") + component_name(c.type, c.normalized);
    }
    if (!allowed) {
        fail(file, field,
             af + " is " + component_name(a.componentType, normalized) + ", which glTF does not allow here (" +
                 allowed_list + ")");
    }
    const AccessorData d = read_accessor(m, index, file, field, a.type, {a.componentType}, max_count);
    Floats f;
    f.count = d.count;
    f.components = tinygltf::GetNumComponentsInType(std::uint32_t(a.type));
    f.values.resize(d.count * std::size_t(f.components));
    const std::size_t size = std::size_t(tinygltf::GetComponentSizeInBytes(std::uint32_t(a.componentType)));
    for (std::size_t i = 0; i < f.values.size(); ++i) {
        const unsigned char* p = d.bytes.data() + i * size;
        double v = 0.0;
        switch (a.componentType) {
            case TINYGLTF_COMPONENT_TYPE_FLOAT: {
                float x;
                std::memcpy(&x, p, 4);
                if (!std::isfinite(x)) {
                    fail(file, field,
                         std::string(element) + " " + std::to_string(i / std::size_t(f.components)) + " of " + af +
                             " is not finite");
                }
                f.values[i] = x;
                continue;
            }
            case TINYGLTF_COMPONENT_TYPE_BYTE:
                v = double(std::int8_t(*p));
                if (normalized) v = std::max(v / 127.0, -1.0);
                break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                v = double(*p);
                if (normalized) v /= 255.0;
                break;
            case TINYGLTF_COMPONENT_TYPE_SHORT: {
                std::int16_t s;
                std::memcpy(&s, p, 2);
                v = normalized ? std::max(double(s) / 32767.0, -1.0) : double(s);
                break;
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                std::uint16_t s;
                std::memcpy(&s, p, 2);
                v = normalized ? double(s) / 65535.0 : double(s);
                break;
            }
            default:
                break;  // not allowed above
        }
        f.values[i] = float(v);
    }
    return f;
}

}  // namespace qs::gltf_read
