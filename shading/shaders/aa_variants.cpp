// The error study's anti-aliasing alternatives of the aastep shaders: 0.7 fwidth instead of the
// gradient's length, and no anti-aliasing (a plain step; the pattern supersampling filters).
// Instantiated apart from the originals so that the two build in parallel.
#include "shading/catalogue.h"
#include "shading/shaders/figure_1_1.h"
#include "shading/shaders/patterns.h"
#include "shading/shaders/table_1_1.h"

namespace qs {

void register_aa_variants(ProgramList& list) {
    using namespace shaders;
    static const ProgramOf<DotsAA<AAWidth::Fwidth>> dots_aa_fwidth;
    static const ProgramOf<DotsAA<AAWidth::Step>> dots_aa_step;
    static const ProgramOf<BricksAA<AAWidth::Fwidth>> bricks_aa_fwidth;
    static const ProgramOf<BricksAA<AAWidth::Step>> bricks_aa_step;
    static const ProgramOf<WorleyTiles<AAWidth::Fwidth>> worley_tiles_fwidth;
    static const ProgramOf<WorleyTiles<AAWidth::Step>> worley_tiles_step;
    static const ProgramOf<Halftone<AAWidth::Fwidth>> halftone_fwidth;
    static const ProgramOf<Halftone<AAWidth::Step>> halftone_step;
    static const ProgramOf<Spots<AAWidth::Length>> spots_length;
    static const ProgramOf<Spots<AAWidth::Step>> spots_step;
    list.insert(list.end(), {&dots_aa_fwidth, &dots_aa_step, &bricks_aa_fwidth, &bricks_aa_step, &worley_tiles_fwidth,
                             &worley_tiles_step, &halftone_fwidth, &halftone_step, &spots_length, &spots_step});
}

}  // namespace qs
