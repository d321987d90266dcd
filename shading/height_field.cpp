#include "shading/height_field.h"

#include <stdexcept>
#include <string>

namespace qs {

namespace {

std::vector<const HeightField*>& registry() {
    static std::vector<const HeightField*> fields;
    return fields;
}

}  // namespace

void register_height_field(const HeightField& field) {
    if (find_height_field(field.shader())) {
        throw std::logic_error("two heights registered for shader '" + std::string(field.shader()) + "'");
    }
    registry().push_back(&field);
}

const HeightField* find_height_field(std::string_view shader) {
    for (const HeightField* f : registry()) {
        if (f->shader() == shader) return f;
    }
    return nullptr;
}

std::vector<const HeightField*> height_fields() { return registry(); }

}  // namespace qs
