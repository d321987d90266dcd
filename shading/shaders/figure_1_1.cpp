// Explicit instantiation of the Figure 1.1 shaders for every number type (see program_of.h).
#include "shading/shaders/figure_1_1.h"

#include "shading/catalogue.h"

namespace qs {

void register_figure_1_1(ProgramList& list) {
    static const ProgramOf<shaders::FlowNoise> flow_noise;
    static const ProgramOf<shaders::Simplex3d> simplex3d;
    static const ProgramOf<shaders::Turbulence> turbulence;
    static const ProgramOf<shaders::Spots<>> spots;
    static const ProgramOf<shaders::Tiles3d> tiles3d;
    list.insert(list.end(), {&flow_noise, &simplex3d, &turbulence, &spots, &tiles3d});
}

}  // namespace qs
