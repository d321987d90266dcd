// Fuzz target: the image reader (textures, `compare` inputs) on hostile files in every format a
// texture may be. The first byte picks the format (as the file's extension would), the rest is
// the file. An ImageError is the expected way out; the size limits must hold before decoding.
#include <cstdint>
#include <iterator>

#include "fuzz/fuzz_check.h"
#include "images/image_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const char* const kNames[] = {"f.png", "f.exr", "f.tif", "f.jpg", "f.hdr"};
    if (size < 1) return 0;
    qs::ImageReadLimits limits;
    limits.max_side = 1024;
    limits.max_pixels = std::uint64_t(1) << 16;  // small: decoding is the fuzzer's time
    try {
        const qs::Image img = qs::decode_image({data + 1, size - 1}, kNames[data[0] % std::size(kNames)], limits);
        FUZZ_CHECK(img.width >= 1 && img.height >= 1 && img.width <= limits.max_side && img.height <= limits.max_side);
        FUZZ_CHECK(std::uint64_t(img.width) * std::uint64_t(img.height) <= limits.max_pixels);
        FUZZ_CHECK(img.rgba.size() == std::size_t(img.width) * std::size_t(img.height) * 4);
    } catch (const qs::ImageError&) {
    }
    return 0;
}
