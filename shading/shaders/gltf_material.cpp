// The default material, instantiated for every number type (see program_of.h).
#include "shading/shaders/gltf_material.h"

namespace qs::shaders {

QUADSHADE_SHADERS_IN("glTF: the default material", GltfMaterial)

}  // namespace qs::shaders
