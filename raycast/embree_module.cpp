// EmbreeScene::create: the Embree module (embree_scene.cpp), loaded on first use.
#include "modules/module_loader.h"
#include "raycast/embree_scene.h"

namespace qs {

namespace {

using CreateScene = EmbreeScene* (*)(int packet_width);

CreateScene module_entry() {
    static const CreateScene entry = [] {
        try {
            return reinterpret_cast<CreateScene>(
                load_module({"embree", "Embree", "by the ray caster", "quadshade_embree_scene"}));
        } catch (const ModuleError& e) {
            throw RayCastError(e.what());
        }
    }();
    return entry;
}

}  // namespace

void EmbreeScene::load_library() { module_entry(); }

std::unique_ptr<EmbreeScene> EmbreeScene::create(int packet_width) {
    return std::unique_ptr<EmbreeScene>(module_entry()(packet_width));
}

}  // namespace qs
