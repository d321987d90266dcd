#include "regression/suite_reports.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "scenes/scene.h"
#include "scenes/scene_files.h"

namespace qs {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Version 2: image paths relative to the fragment's own folder (absolute when it was streamed).
constexpr const char* kFragmentFormat = "quadshade-test-fragment/2";

std::size_t count(const SuiteRun& run, CaseStatus s) {
    return std::size_t(std::count_if(run.results.begin(), run.results.end(), [s](const CaseResult& r) { return r.status == s; }));
}

double total_seconds(const SuiteRun& run) {
    double t = 0.0;
    for (const CaseResult& r : run.results) t += r.seconds;
    return t;
}

// Text for XML and HTML, attributes included.
std::string escaped(const std::string& s) {
    std::string out;
    for (const char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&#39;"; break;
            default: out += (c >= 0 && c < 0x20 && c != '\n' && c != '\t') ? ' ' : c;
        }
    }
    return out;
}

// A report: written whole by output_file.h's rule (its folder made if missing), or streamed
// into a standard stream, FIFO or character device.
void write_report(const fs::path& file, const std::string& text) {
    if (output_place(file, Streams::Allowed) == OutputPlace::File)
        make_output_folder(file.parent_path(), FolderLink::Followed);
    write_output(file, text, Streams::Allowed);
}

// A fragment's fields, each checked: its kind, its range, no control character in a string (a
// NUL would cut the names and messages made of it); errors name the field.
struct FragmentReader {
    std::string file;
    fs::path folder;  // where its relative paths lead from
    const MergeOptions& options;

    [[noreturn]] void fail(const std::string& field, const std::string& what) const {
        throw std::runtime_error(file + ": " + field + ": " + what);
    }
    const json& at(const json& object, const char* key, const std::string& field) const {
        if (!object.is_object()) fail(field, "expected an object");
        const auto it = object.find(key);
        if (it == object.end()) fail(field + "." + key, "missing");
        return *it;
    }
    long long integer(const json& object, const char* key, const std::string& field, long long lo, long long hi) const {
        const json& v = at(object, key, field);
        const std::string f = field.empty() ? key : field + "." + key;
        if (!v.is_number_integer()) fail(f, "expected a whole number");
        // A JSON integer without a sign is read as unsigned, 0 included: both bounds hold for it too.
        const bool in_range = v.is_number_unsigned()
                                  ? v.get<unsigned long long>() <= (unsigned long long)hi &&
                                        (lo <= 0 || v.get<unsigned long long>() >= (unsigned long long)lo)
                                  : v.get<long long>() >= lo && v.get<long long>() <= hi;
        if (!in_range) {
            fail(f, "expected a whole number within " + std::to_string(lo) + ".." + std::to_string(hi));
        }
        return v.get<long long>();
    }
    std::string text(const json& object, const char* key, const std::string& field, bool lines = false) const {
        const json& v = at(object, key, field);
        const std::string f = field.empty() ? key : field + "." + key;
        if (!v.is_string()) fail(f, "expected a string");
        std::string s = v.get<std::string>();
        for (const char c : s) {
            if (((unsigned char)c < 0x20 && !(lines && (c == '\n' || c == '\t'))) || c == 0x7f) {
                fail(f, "holds a control character (such as NUL)");
            }
        }
        return s;
    }
    // An image's path: relative to the fragment's folder; inside it when the images are read,
    // unless allowed.
    fs::path image(const json& object, const char* key, const std::string& field) const {
        const std::string s = text(object, key, field);
        if (s.empty()) return {};
        if (options.reads_images) {
            try {
                return resolve_scene_uri(file, s, {options.allow_outside}, "report fragment");
            } catch (const SceneError& e) {
                fail(field + "." + key, e.what());
            }
        }
        const fs::path p(s);
        return p.is_absolute() ? p : (folder / p).lexically_normal();
    }
};

CaseStatus status_from(const std::string& s, const FragmentReader& in, const std::string& field) {
    for (CaseStatus c : {CaseStatus::Pass, CaseStatus::Warn, CaseStatus::Fail, CaseStatus::Updated}) {
        if (s == status_name(c)) return c;
    }
    in.fail(field, "unknown status '" + s + "' (PASS, WARN, FAIL, UPDATED)");
}

}  // namespace

const char* status_name(CaseStatus s) {
    switch (s) {
        case CaseStatus::Pass: return "PASS";
        case CaseStatus::Warn: return "WARN";
        case CaseStatus::Fail: return "FAIL";
        case CaseStatus::Updated: return "UPDATED";
    }
    return "?";
}

int summarize(const SuiteRun& run) {
    const std::size_t failed = count(run, CaseStatus::Fail);
    std::printf("quadshade test: %s", run.suite.c_str());
    if (run.shards > 1 && run.shard > 0) std::printf(" shard %d/%d", run.shard, run.shards);
    std::printf(": %zu cases, %zu passed, %zu warned, %zu failed, %zu updated (%.1f s of rendering and comparing", run.results.size(),
                count(run, CaseStatus::Pass), count(run, CaseStatus::Warn), failed, count(run, CaseStatus::Updated),
                total_seconds(run));
    if (run.shard == 0) std::printf(", %d shards merged", run.shards);
    std::printf(")\n");
    for (const CaseResult& r : run.results) {
        if (r.status != CaseStatus::Fail) continue;
        std::printf("  FAIL %s: %s\n", r.name.c_str(), r.message.c_str());
        if (!r.actual.empty()) std::printf("       expected %s, actual %s", r.expected.c_str(), r.actual.c_str());
        if (!r.diff.empty()) std::printf(", difference %s", r.diff.c_str());
        if (!r.actual.empty()) std::printf("\n");
    }
    return failed ? 3 : 0;
}

void write_fragment(const SuiteRun& run, const fs::path& file) {
    // Paths relative to the fragment's folder, so that a results folder moves with its images; a
    // streamed fragment has no folder of its own and names them in full.
    const bool streamed = output_place(file, Streams::Allowed) == OutputPlace::Stream;
    const fs::path home = entry_path(file).parent_path();
    auto named = [&](const fs::path& p) -> std::string {
        if (p.empty()) return "";
        const fs::path full = entry_path(p);
        return streamed ? full.string() : full.lexically_relative(home).string();
    };
    json results = json::array();
    for (const CaseResult& r : run.results) {
        results.push_back({{"name", r.name},
                           {"index", r.index},
                           {"status", status_name(r.status)},
                           {"message", r.message},
                           {"pixels", r.pixels},
                           {"failing", r.failing},
                           {"warning", r.warning},
                           {"max_steps", r.max_steps},
                           {"seconds", r.seconds},
                           {"expected", named(r.expected)},
                           {"actual", named(r.actual)},
                           {"diff", named(r.diff)}});
    }
    const json doc = {{"format", kFragmentFormat}, {"suite", run.suite},         {"shard", run.shard},
                      {"shards", run.shards},      {"suite_cases", run.suite_cases}, {"results", results}};
    write_report(file, doc.dump(1, ' ', false, json::error_handler_t::replace) + "\n");
}

SuiteRun parse_fragment(std::string_view text, const fs::path& file, const MergeOptions& options) {
    const std::string name = file.string();
    check_json_depth(text, name);
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::exception& e) {
        throw std::runtime_error(name + ": not a report fragment: " + e.what());
    }
    const FragmentReader in{name, file.parent_path(), options};
    if (!doc.is_object() || !doc.contains("format") || doc["format"] != kFragmentFormat) {
        in.fail("format", "not " + std::string(kFragmentFormat) + " (a report fragment of this quadshade)");
    }
    SuiteRun part;
    part.suite = in.text(doc, "suite", "");
    part.shards = int(in.integer(doc, "shards", "", 1, kSuiteShards));
    part.shard = int(in.integer(doc, "shard", "", 1, part.shards));
    part.suite_cases = std::size_t(in.integer(doc, "suite_cases", "", 1, (long long)kSuiteCases));
    const json& results = in.at(doc, "results", "");
    if (!results.is_array()) in.fail("results", "expected an array");
    if (results.size() > part.suite_cases)
        in.fail("results", "more results than the suite's " + std::to_string(part.suite_cases) + " cases");
    std::set<std::string> names;
    for (std::size_t i = 0; i < results.size(); ++i) {
        const json& j = results[i];
        const std::string field = "results[" + std::to_string(i) + "]";
        CaseResult r;
        r.name = in.text(j, "name", field);
        if (!is_case_name(r.name)) in.fail(field + ".name", "not a case's name (letters, digits, '-', '_' and '.')");
        if (!names.insert(r.name).second) in.fail(field + ".name", "'" + r.name + "' is an earlier result's name");
        r.index = std::size_t(in.integer(j, "index", field, 0, (long long)part.suite_cases - 1));
        r.status = status_from(in.text(j, "status", field), in, field + ".status");
        r.message = in.text(j, "message", field, /*lines=*/true);
        constexpr long long kPixels = 1LL << 32;  // 32768 x 32768 is 2^30
        r.pixels = in.integer(j, "pixels", field, 0, kPixels);
        r.failing = in.integer(j, "failing", field, 0, r.pixels);
        r.warning = in.integer(j, "warning", field, 0, r.pixels);
        r.max_steps = int(in.integer(j, "max_steps", field, 0, 255));
        const json& seconds = in.at(j, "seconds", field);
        if (!seconds.is_number() || !std::isfinite(seconds.get<double>()) || seconds.get<double>() < 0.0) {
            in.fail(field + ".seconds", "expected a number of seconds");
        }
        r.seconds = seconds.get<double>();
        r.expected = in.image(j, "expected", field);
        r.actual = in.image(j, "actual", field);
        r.diff = in.image(j, "diff", field);
        part.results.push_back(std::move(r));
    }
    return part;
}

SuiteRun merge_fragments(const std::vector<fs::path>& files, const MergeOptions& options) {
    SuiteRun merged;
    std::map<int, std::string> shards_seen;
    std::map<std::string, std::string> names_seen;  // case name -> the fragment holding it
    for (const fs::path& file : files) {
        const std::string name = file.string();
        SuiteRun part = parse_fragment(read_suite_json(file, options.memory_limit), file, options);
        if (shards_seen.empty()) {
            merged.suite = part.suite, merged.shards = part.shards, merged.suite_cases = part.suite_cases;
        } else if (part.suite != merged.suite || part.shards != merged.shards ||
                   part.suite_cases != merged.suite_cases) {
            throw std::runtime_error(name + ": suite, shards or suite_cases: not those of " + files.front().string());
        }
        if (const auto [it, added] = shards_seen.emplace(part.shard, name); !added) {
            throw std::runtime_error(name + ": shard " + std::to_string(part.shard) + " is also " + it->second);
        }
        for (CaseResult& r : part.results) {
            if (const auto [it, added] = names_seen.emplace(r.name, name); !added) {
                throw std::runtime_error(name + ": case '" + r.name + "' is also in " + it->second);
            }
            if (merged.results.size() == merged.suite_cases) {
                throw std::runtime_error(name + ": the fragments hold more results than the suite's " +
                                         std::to_string(merged.suite_cases) + " cases");
            }
            merged.results.push_back(std::move(r));
        }
    }
    if (int(shards_seen.size()) != merged.shards) {
        // The first few missing, and how many: a fragment may claim any number of shards.
        std::string missing;
        int listed = 0;
        for (int k = 1; k <= merged.shards && listed < 10; ++k) {
            if (!shards_seen.count(k)) missing += (listed++ ? ", " : "") + std::to_string(k);
        }
        const int absent = merged.shards - int(shards_seen.size());
        if (absent > listed) missing += " and " + std::to_string(absent - listed) + " more";
        throw std::runtime_error("the fragments lack shard " + missing + " of " + std::to_string(merged.shards));
    }
    merged.shard = 0;  // all of them
    std::sort(merged.results.begin(), merged.results.end(), [](const CaseResult& a, const CaseResult& b) { return a.index < b.index; });
    for (std::size_t i = 0; i < merged.results.size(); ++i) {
        if (merged.results[i].index != i || merged.results.size() != merged.suite_cases) {
            throw std::runtime_error("the fragments do not hold each of the suite's " + std::to_string(merged.suite_cases) +
                                     " cases once (a shard run with another suite file?)");
        }
    }
    return merged;
}

void write_junit(const SuiteRun& run, const fs::path& file) {
    const std::size_t failed = count(run, CaseStatus::Fail);
    char header[512];
    std::snprintf(header, sizeof header, "tests=\"%zu\" failures=\"%zu\" errors=\"0\" skipped=\"0\" time=\"%.3f\"", run.results.size(),
                  failed, total_seconds(run));
    std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    x += "<testsuites name=\"quadshade test\" " + std::string(header) + ">\n";
    x += "  <testsuite name=\"" + escaped(run.suite) + "\" " + header + ">\n";
    for (const CaseResult& r : run.results) {
        char time[32];
        std::snprintf(time, sizeof time, "%.3f", r.seconds);
        x += "    <testcase classname=\"" + escaped(run.suite) + "\" name=\"" + escaped(r.name) + "\" time=\"" + time + "\"";
        if (r.status == CaseStatus::Fail) {
            x += ">\n      <failure message=\"" + escaped(r.message) + "\" type=\"image difference\">expected: " +
                 escaped(r.expected.string());
            if (!r.actual.empty()) x += "\nactual: " + escaped(r.actual.string());
            if (!r.diff.empty()) x += "\ndifference: " + escaped(r.diff.string());
            x += "</failure>\n    </testcase>\n";
        } else if (!r.message.empty()) {
            x += ">\n      <system-out>" + std::string(status_name(r.status)) + ": " + escaped(r.message) + "</system-out>\n    </testcase>\n";
        } else {
            x += "/>\n";
        }
    }
    x += "  </testsuite>\n</testsuites>\n";
    write_report(file, x);
}

namespace {

const char* const kHtmlImages[] = {"expected", "actual", "diff"};

fs::path html_image(const fs::path& folder, const std::string& case_name, const char* what) {
    return folder / "images" / (case_name + "." + what + ".png");  // case names are file names (is_case_name)
}

}  // namespace

std::vector<fs::path> html_files(const SuiteRun& run, const fs::path& folder) {
    std::vector<fs::path> files{folder / "index.html"};
    for (const CaseResult& r : run.results) {
        for (const char* what : kHtmlImages) files.push_back(html_image(folder, r.name, what));
    }
    return files;
}

std::vector<fs::path> html_files(const Suite& suite, const fs::path& folder) {
    std::vector<fs::path> files{folder / "index.html"};
    for (const SuiteCase& c : suite.cases) {
        for (const char* what : kHtmlImages) files.push_back(html_image(folder, c.name, what));
    }
    return files;
}

void write_html(const SuiteRun& run, const fs::path& folder) {
    make_output_folder(folder, FolderLink::Followed);
    // The images are copied beside the page, so that it stays whole when the run's folder goes;
    // into a folder of the page's own (a link planted there is refused, never followed).
    make_output_folder(folder / "images", FolderLink::Refused);
    auto image = [&](const fs::path& file, const CaseResult& r, const char* what) -> std::string {
        std::error_code ec;
        if (file.empty() || !fs::exists(file, ec)) return "<td class=\"none\">-</td>";
        const fs::path copy = html_image(folder, r.name, what);
        copy_to_output(file, copy);
        const std::string name = copy.filename().string();
        return "<td><a href=\"images/" + escaped(name) + "\"><img src=\"images/" + escaped(name) + "\" alt=\"" + what + "\"></a></td>";
    };
    const std::size_t failed = count(run, CaseStatus::Fail);
    std::string h = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>quadshade test: " + escaped(run.suite) +
                    "</title>\n<style>body{font-family:sans-serif;margin:1.5em}table{border-collapse:collapse}"
                    "td,th{border:1px solid #ccc;padding:4px;vertical-align:top;text-align:left}"
                    "img{max-width:256px;image-rendering:pixelated;background:repeating-conic-gradient(#ddd 0 25%,#fff 0 50%) 0/16px 16px}"
                    ".PASS{color:#070}.WARN{color:#a60}.FAIL{color:#c00;font-weight:bold}.UPDATED{color:#06c}</style></head><body>\n";
    char line[512];
    std::snprintf(line, sizeof line, "<h1>%s</h1>\n<p>%zu cases: %zu passed, %zu warned, %zu failed, %zu updated.</p>\n",
                  escaped(run.suite).c_str(), run.results.size(), count(run, CaseStatus::Pass), count(run, CaseStatus::Warn), failed,
                  count(run, CaseStatus::Updated));
    h += line;
    h += "<table>\n<tr><th>case</th><th>result</th><th>expected</th><th>actual</th><th>difference (full scale 8/255)</th></tr>\n";
    for (const CaseResult& r : run.results) {
        std::snprintf(line, sizeof line, "max %d/255, %lld over the fail threshold, %lld over warn, of %lld pixels; %.0f ms", r.max_steps,
                      r.failing, r.warning, r.pixels, r.seconds * 1e3);
        h += "<tr><td>" + escaped(r.name) + "</td><td><span class=\"" + status_name(r.status) + "\">" + status_name(r.status) +
             "</span><br>" + escaped(r.message) + "<br><small>" + line + "</small></td>" + image(r.expected, r, "expected") +
             image(r.actual, r, "actual") + image(r.diff, r, "diff") + "</tr>\n";
    }
    h += "</table>\n</body></html>\n";
    write_output(folder / "index.html", h);
}

}  // namespace qs
