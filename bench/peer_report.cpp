#include "bench/peer_report.h"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace qs::bench {

namespace {

constexpr std::string_view kRendererTag = "quadshade-peer-renderer ";
constexpr std::string_view kTimingTag = "quadshade-peer-timing ";

std::string number(double v) {
    char buffer[64];
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);  // shortest round-trip form
    return std::string(buffer, r.ptr);
}

[[noreturn]] void fail(const std::string& what) { throw std::runtime_error("peer report: " + what); }

// "'text'" (built by appending: GCC 12 warns falsely about "'" + std::string).
std::string quoted(std::string_view text) {
    std::string s = "'";
    s.append(text);
    s += '\'';
    return s;
}

double parse_number(std::string_view key, std::string_view text) {
    double v = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size()) {
        fail(quoted(key) + " is not a number: " + quoted(text));
    }
    if (!std::isfinite(v) || v < 0) fail(quoted(key) + " is not a finite time: " + quoted(text));
    return v;
}

}  // namespace

std::string format_peer_report(const PeerReport& r) {
    return std::string(kRendererTag) + r.renderer + "\n" + std::string(kTimingTag) + "median_ms=" + number(r.median_ms) +
           " min_ms=" + number(r.min_ms) + " max_ms=" + number(r.max_ms) + " setup_ms=" + number(r.setup_ms) + "\n";
}

PeerReport parse_peer_report(std::string_view text) {
    std::optional<std::string> renderer;
    std::optional<std::string_view> timing;
    while (!text.empty()) {
        const std::size_t end = text.find('\n');
        std::string_view line = text.substr(0, end);
        text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (line.starts_with(kRendererTag)) {
            if (renderer) fail("two renderer lines");
            renderer = std::string(line.substr(kRendererTag.size()));
        } else if (line.starts_with(kTimingTag)) {
            if (timing) fail("two timing lines");
            timing = line.substr(kTimingTag.size());
        }
    }
    if (!renderer || renderer->empty()) fail("no renderer line");
    if (!timing) fail("no timing line");

    PeerReport report;
    report.renderer = *renderer;
    struct Field {
        std::string_view key;
        double* value;
        bool seen = false;
    };
    Field fields[] = {{"median_ms", &report.median_ms}, {"min_ms", &report.min_ms},
                      {"max_ms", &report.max_ms}, {"setup_ms", &report.setup_ms}};
    std::string_view rest = *timing;
    while (!rest.empty()) {
        const std::size_t space = rest.find(' ');
        const std::string_view token = rest.substr(0, space);
        rest = space == std::string_view::npos ? std::string_view() : rest.substr(space + 1);
        if (token.empty()) continue;
        const std::size_t eq = token.find('=');
        if (eq == std::string_view::npos) fail(quoted(token) + " is not key=value");
        const std::string_view key = token.substr(0, eq);
        Field* field = nullptr;
        for (Field& f : fields) field = f.key == key ? &f : field;
        if (!field) fail("unknown field " + quoted(key));
        if (field->seen) fail(quoted(key) + " given twice");
        *field->value = parse_number(key, token.substr(eq + 1));
        field->seen = true;
    }
    for (const Field& f : fields) {
        if (!f.seen) fail("no " + quoted(f.key));
    }
    if (!(report.min_ms <= report.median_ms && report.median_ms <= report.max_ms)) {
        fail("min <= median <= max does not hold");
    }
    return report;
}

std::optional<int> vector_bits_of(std::string_view renderer) {
    const std::size_t at = renderer.rfind(" bits)");
    if (at == std::string_view::npos) return std::nullopt;
    std::size_t begin = at;
    while (begin > 0 && renderer[begin - 1] >= '0' && renderer[begin - 1] <= '9') --begin;
    int bits = 0;
    const auto r = std::from_chars(renderer.data() + begin, renderer.data() + at, bits);
    if (begin == at || r.ec != std::errc()) return std::nullopt;
    return bits;
}

}  // namespace qs::bench
