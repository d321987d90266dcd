// Explicit instantiation of the pattern shaders for every number type (see program_of.h).
#include "shading/shaders/patterns.h"

#include "shading/catalogue.h"

namespace qs {

void register_patterns(ProgramList& list) {
    using namespace shaders;
    static const ProgramOf<PatternS> pattern_s;
    static const ProgramOf<Lines> lines;
    static const ProgramOf<Ridges> ridges;
    static const ProgramOf<Checker> checker;
    static const ProgramOf<Wave> wave;
    static const ProgramOf<WaveAA> wave_aa;
    static const ProgramOf<Bricks> bricks;
    static const ProgramOf<BricksAA<>> bricks_aa;
    static const ProgramOf<DotsAA<>> dots_aa;
    static const ProgramOf<Facets> facets;
    static const ProgramOf<Blobs> blobs;
    static const ProgramOf<Rings> rings;
    static const ProgramOf<Simplex2d<noise::Simplex2dCorner::Correct>> simplex2d;
    static const ProgramOf<Simplex2d<noise::Simplex2dCorner::SeedTypo>> simplex2d_seed_typo;
    static const ProgramOf<Cellular2x2> cellular2x2;
    static const ProgramOf<GradientAA> gradient_aa;
    list.insert(list.end(), {&pattern_s, &lines, &ridges, &checker, &wave, &wave_aa, &bricks, &bricks_aa, &dots_aa,
                             &facets, &blobs, &rings, &simplex2d, &simplex2d_seed_typo, &cellular2x2, &gradient_aa});
}

}  // namespace qs
