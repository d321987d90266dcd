# Read by ctest, not by CMake: the slowest tests' seconds (a Release build's, measured on a 2-core
# host), so that a fresh clone's ctest, which has no timings of its own yet, starts them
# first and the other core runs the short tests beside them, instead of ending on them alone. Only
# the order matters; ctest keeps its own measured costs once it has run (Testing/Temporary), and a
# name here that a build does not have (QUADSHADE_REFERENCE=OFF) is ignored.
set(slowest_tests
    "every shader matches OSMesa softpipe under the coarse-lower rule" 283
    "check: every catalogue shader meets the bar on the shipped scenes (llvmpipe)" 123
    "every shader matches OSMesa llvmpipe under the fine rule" 107
    "examples/ build against the installed package as the README says, optimised, and match OSMesa" 58
    "docs/writing-shaders.md: its examples build as a plugin and match OSMesa" 44
    "conformance vs softpipe: torus under a rolled camera" 36
    "plugins: an edited .frag reaches the build folder; an unoptimised plugin is warned about" 30
    "check: against softpipe (coarse-lower) the faithful translation passes and the wrong one fails" 27
    "quadshade translate builds a plugin against the installed package, --compile caches it" 26
    "conformance vs softpipe: 200x200 plane from 0.3 above, crossing the near plane" 24)
while(slowest_tests)
    list(POP_FRONT slowest_tests name seconds)
    set_tests_properties("${name}" PROPERTIES COST ${seconds})
endwhile()
