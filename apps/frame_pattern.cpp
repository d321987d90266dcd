#include "apps/frame_pattern.h"

#include <filesystem>
#include <stdexcept>

namespace qs {

std::string frame_path(const std::string& pattern, int frame) {
    if (pattern.find('%') == std::string::npos) {
        const std::filesystem::path p(pattern);
        std::string number = std::to_string(frame);
        number.insert(0, number.size() < 4 ? 4 - number.size() : 0, '0');
        return (p.parent_path() / (p.stem().string() + "_" + number + p.extension().string())).string();
    }
    std::string out;
    bool numbered = false;
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') {
            out += pattern[i];
            continue;
        }
        std::size_t k = i + 1, width = 0;
        if (k < pattern.size() && pattern[k] == '%') {
            out += '%', i = k;
            continue;
        }
        if (k + 1 < pattern.size() && pattern[k] == '0' && pattern[k + 1] >= '1' && pattern[k + 1] <= '9') {
            width = std::size_t(pattern[k + 1] - '0'), k += 2;
        }
        if (k >= pattern.size() || pattern[k] != 'd') {
            throw std::invalid_argument("-o '" + pattern + "': only %d, %0Nd (N = 1..9) and %% may follow a '%' in a frame pattern");
        }
        std::string number = std::to_string(frame);
        number.insert(0, number.size() < width ? width - number.size() : 0, '0');
        out += number, i = k, numbered = true;
    }
    if (!numbered) throw std::invalid_argument("-o '" + pattern + "': a frame pattern needs %d or %0Nd for the frame number");
    return out;
}

}  // namespace qs
