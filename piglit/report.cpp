#include "piglit/report.h"

#include <algorithm>
#include <array>
#include <fstream>
#include <map>
#include <stdexcept>

namespace qs::piglit {

namespace {

constexpr std::array<Status, 5> kStatuses = {Status::Pass, Status::Fail, Status::Skip, Status::Warn, Status::Crash};

std::string xml_escaped(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default:
                // XML 1.0 allows no control characters but tab and line breaks.
                if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') {
                    out += '?';
                } else {
                    out += c;
                }
        }
    }
    return out;
}

std::string probe_values(const std::array<float, 4>& v, int components) {
    std::string s;
    char buffer[32];
    for (int c = 0; c < components; ++c) {
        std::snprintf(buffer, sizeof buffer, "%s%.4f", c ? " " : "", double(v[std::size_t(c)]));
        s += buffer;
    }
    return s;
}

std::string probe_text(const ProbeMismatch& p) {
    char head[96];
    std::snprintf(head, sizeof head, "line %d: ", p.line);
    std::string s = std::string(head) + p.command + "\n";
    std::snprintf(head, sizeof head, "    at (%d, %d): expected ", p.x, p.y);
    s += head + probe_values(p.expected, p.components) + ", observed " + probe_values(p.observed, p.components);
    if (p.pixels > 1) s += " (" + std::to_string(p.pixels) + " pixels differ)";
    return s;
}

// A failure's message and its probes' mismatches, a line each.
std::string failure_details(const TestResult& r) {
    std::string details = r.message;
    for (const ProbeMismatch& p : r.probes) {
        if (!details.empty()) details += '\n';
        details += probe_text(p);
    }
    return details;
}

}  // namespace

std::string test_name(const std::string& file) {
    std::string name = file;
    const std::size_t spec = name.rfind("spec/");
    if (spec != std::string::npos) name = name.substr(spec + 5);
    const std::string ext = ".shader_test";
    if (name.size() > ext.size() && name.compare(name.size() - ext.size(), ext.size(), ext) == 0) name.resize(name.size() - ext.size());
    return name;
}

std::string test_group(const std::string& file) {
    const std::string name = test_name(file);
    const std::size_t first = name.find('/');
    if (first == std::string::npos) return ".";
    const std::size_t second = name.find('/', first + 1);
    if (second == std::string::npos) return name.substr(0, first);
    return name.substr(0, second);
}

void print_result(std::FILE* out, const TestResult& r) {
    std::fprintf(out, "%s: %s", status_word(r.status), test_name(r.file).c_str());
    if (r.status == Status::Skip) std::fprintf(out, " (%s)", r.reason.c_str());
    std::fprintf(out, "\n");
    if (r.status == Status::Pass || r.status == Status::Skip) return;
    const std::string details = failure_details(r);
    std::size_t at = 0;
    while (at < details.size()) {
        std::size_t end = details.find('\n', at);
        if (end == std::string::npos) end = details.size();
        std::fprintf(out, "    %s\n", details.substr(at, end - at).c_str());
        at = end + 1;
    }
}

void print_summary(std::FILE* out, const std::vector<TestResult>& results, double seconds) {
    std::map<std::string, std::array<std::size_t, 5>> groups;
    std::array<std::size_t, 5> total{};
    std::map<std::string, std::size_t> reasons;
    for (const TestResult& r : results) {
        ++groups[test_group(r.file)][std::size_t(r.status)];
        ++total[std::size_t(r.status)];
        if (r.status == Status::Skip) ++reasons[r.reason];
    }
    std::size_t width = 6;
    for (const auto& [g, n] : groups) width = std::max(width, g.size());
    std::fprintf(out, "\n%-*s %7s %7s %7s %7s %7s %7s\n", int(width), "folder", "pass", "fail", "skip", "warn", "crash", "total");
    const auto row = [&](const std::string& name, const std::array<std::size_t, 5>& n) {
        std::fprintf(out, "%-*s", int(width), name.c_str());
        std::size_t sum = 0;
        for (Status s : kStatuses) {
            std::fprintf(out, " %7zu", n[std::size_t(s)]);
            sum += n[std::size_t(s)];
        }
        std::fprintf(out, " %7zu\n", sum);
    };
    for (const auto& [g, n] : groups) row(g, n);
    row("all", total);
    if (!reasons.empty()) {
        std::vector<std::pair<std::size_t, std::string>> by_count;
        for (const auto& [reason, n] : reasons) by_count.emplace_back(n, reason);
        std::sort(by_count.begin(), by_count.end(), [](const auto& a, const auto& b) {
            return a.first != b.first ? a.first > b.first : a.second < b.second;
        });
        std::fprintf(out, "\nskipped, by reason:\n");
        for (const auto& [n, reason] : by_count) std::fprintf(out, "%7zu  %s\n", n, reason.c_str());
    }
    std::fprintf(out, "\n%zu tests in %.1f s\n", results.size(), seconds);
}

void write_junit(const std::filesystem::path& path, const std::vector<TestResult>& results) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw std::runtime_error(path.string() + ": cannot write the JUnit report");
    std::array<std::size_t, 5> n{};
    for (const TestResult& r : results) ++n[std::size_t(r.status)];
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out << "<testsuites>\n<testsuite name=\"piglit\" tests=\"" << results.size() << "\" failures=\""
        << n[std::size_t(Status::Fail)] << "\" errors=\"" << n[std::size_t(Status::Crash)] << "\" skipped=\""
        << n[std::size_t(Status::Skip)] << "\">\n";
    for (const TestResult& r : results) {
        const std::string name = test_name(r.file);
        const std::size_t slash = name.rfind('/');
        // As piglit's JUnit backend: each folder a level, the dots within a name made '_'.
        std::string folder = slash == std::string::npos ? std::string() : name.substr(0, slash);
        std::replace(folder.begin(), folder.end(), '.', '_');
        std::replace(folder.begin(), folder.end(), '/', '.');
        const std::string classname = "piglit" + (folder.empty() ? std::string() : "." + folder);
        out << "  <testcase classname=\"" << xml_escaped(classname) << "\" name=\""
            << xml_escaped(slash == std::string::npos ? name : name.substr(slash + 1)) << "\" time=\"" << r.seconds
            << "\" status=\"" << status_word(r.status) << "\">";
        const std::string details = failure_details(r);
        switch (r.status) {
            case Status::Fail:
                out << "<failure type=\"fail\" message=\"" << xml_escaped(details.substr(0, details.find('\n'))) << "\">"
                    << xml_escaped(details) << "</failure>";
                break;
            case Status::Crash: out << "<error type=\"crash\">" << xml_escaped(details) << "</error>"; break;
            case Status::Skip: out << "<skipped type=\"skip\" message=\"" << xml_escaped(r.reason) << "\"/>"; break;
            case Status::Warn: out << "<system-out>" << xml_escaped(details) << "</system-out>"; break;
            case Status::Pass: break;
        }
        out << "</testcase>\n";
    }
    out << "</testsuite>\n</testsuites>\n";
    if (!out) throw std::runtime_error(path.string() + ": cannot write the JUnit report");
}

}  // namespace qs::piglit
