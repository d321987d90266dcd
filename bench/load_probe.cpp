// quadshade-load-probe-LIBRARY: a program that links one library (the QUADSHADE_PROBE_* macro its
// target defines) and calls one of its cheapest functions, or links none (the C++ runtime alone).
// quadshade-bench-startup times each: what loading that library costs a process on its own.

#include <iostream>

#if defined(QUADSHADE_PROBE_OPENIMAGEIO)
#include <OpenImageIO/imageio.h>
#elif defined(QUADSHADE_PROBE_EMBREE)
#include <embree3/rtcore.h>
#elif defined(QUADSHADE_PROBE_TBB)
#include <tbb/task_arena.h>
#elif defined(QUADSHADE_PROBE_OSMESA)
#include <GL/osmesa.h>
#elif defined(QUADSHADE_PROBE_LIBPNG)
#include <png.h>
#endif

int main() {
    bool linked = std::cout.good();
#if defined(QUADSHADE_PROBE_OPENIMAGEIO)
    linked = OIIO::openimageio_version() > 0;
#elif defined(QUADSHADE_PROBE_EMBREE)
    linked = rtcGetDeviceError(nullptr) == RTC_ERROR_NONE;
#elif defined(QUADSHADE_PROBE_TBB)
    linked = tbb::this_task_arena::max_concurrency() > 0;
#elif defined(QUADSHADE_PROBE_OSMESA)
    linked = OSMesaGetCurrentContext() == nullptr;
#elif defined(QUADSHADE_PROBE_LIBPNG)
    linked = png_access_version_number() > 0;
#endif
    return linked ? 0 : 1;
}
