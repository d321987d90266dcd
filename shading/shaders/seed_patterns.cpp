// Explicit instantiation of the seed shaders for every number type (see program_of.h).
#include "shading/shaders/seed_patterns.h"

#include "shading/catalogue.h"

namespace qs {

void register_seed_patterns(ProgramList& list) {
    static const ProgramOf<shaders::PcgValueNoise> pcg_value_noise;
    static const ProgramOf<shaders::Mandelbrot> mandelbrot;
    list.insert(list.end(), {&pcg_value_noise, &mandelbrot});
}

}  // namespace qs
