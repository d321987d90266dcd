// Explicit instantiation of the Table 1.1 shaders for every number type (see program_of.h).
#include "shading/shaders/table_1_1.h"

#include "shading/catalogue.h"

namespace qs {

void register_table_1_1(ProgramList& list) {
    static const ProgramOf<shaders::ConstantColor> constant_color;
    static const ProgramOf<shaders::SingleTexture> single_texture;
    static const ProgramOf<shaders::Dots> dots;
    static const ProgramOf<shaders::Perlin> perlin;
    static const ProgramOf<shaders::Perlin5> perlin5;
    static const ProgramOf<shaders::Worley> worley;
    static const ProgramOf<shaders::WorleyTiles<>> worley_tiles;
    static const ProgramOf<shaders::Halftone<>> halftone;
    list.insert(list.end(), {&constant_color, &single_texture, &dots, &perlin, &perlin5, &worley,
                             &worley_tiles, &halftone});
}

}  // namespace qs
