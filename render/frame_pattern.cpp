#include "render/frame_pattern.h"

#include <charconv>
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

std::optional<int> frame_named(const std::string& pattern, const std::string& name, int first, int last) {
    if (pattern.find('%') == std::string::npos) return frame_named(resolved_pattern(pattern), name, first, last);
    // The first frame number's place: after the literal text before the first %d or %0Nd.
    std::string before;
    std::size_t i = 0;
    for (; i < pattern.size(); ++i) {
        if (pattern[i] != '%') {
            before += pattern[i];
        } else if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            before += '%', ++i;
        } else {
            break;
        }
    }
    if (!name.starts_with(before)) return std::nullopt;
    const std::size_t at = before.size();
    std::size_t digits = 0;
    while (at + digits < name.size() && digits < 10 && name[at + digits] >= '0' && name[at + digits] <= '9') ++digits;
    for (std::size_t n = 1; n <= digits; ++n) {
        int frame = 0;
        const auto [end, ec] = std::from_chars(name.data() + at, name.data() + at + n, frame);
        if (ec != std::errc() || frame < first || frame > last) continue;
        if (frame_path(pattern, frame) == name) return frame;
    }
    return std::nullopt;
}

std::string resolved_pattern(const std::string& pattern) {
    namespace fs = std::filesystem;
    const fs::path p(pattern);
    const std::string folder = p.parent_path().string();
    if (folder.find('%') != std::string::npos) return fs::absolute(p).lexically_normal().string();
    std::error_code ec;
    const fs::path real = fs::weakly_canonical(folder.empty() ? fs::path(".") : fs::path(folder), ec);
    std::string out;
    for (const char c : (ec ? fs::absolute(folder).lexically_normal() : real).string())
        out += c == '%' ? "%%" : std::string(1, c);
    if (!out.empty() && out.back() != '/') out += '/';
    const std::string file = p.filename().string();
    if (file.find('%') != std::string::npos) return out + file;
    return out + p.stem().string() + "_%04d" + p.extension().string();  // frame_path's form for a plain name
}

}  // namespace qs
