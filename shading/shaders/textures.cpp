// Explicit instantiation of the shaders that sample named textures (see program_of.h).
#include "shading/shaders/textures.h"

#include "shading/catalogue.h"

namespace qs {

void register_texture_shaders(ProgramList& list) {
    static const ProgramOf<shaders::TextureLodProbe> texture_lod_probe;
    static const ProgramOf<shaders::TextureBiasProbe> texture_bias_probe;
    static const ProgramOf<shaders::Texture3dProbe> texture3d_probe;
    static const ProgramOf<shaders::Texture3dLodProbe> texture3d_lod_probe;
    static const ProgramOf<shaders::FastNoise> fast_noise;
    list.insert(list.end(), {&texture_lod_probe, &texture_bias_probe, &texture3d_probe, &texture3d_lod_probe, &fast_noise});
}

}  // namespace qs
