// The reports of a golden-image suite run: the terminal summary, report fragments (one per shard)
// and their merge, JUnit XML (as CI systems read it) and an HTML page with the images side by side.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "apps/golden_suite.h"

namespace qs {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr const char* kFragmentFormat = "quadshade-test-fragment/1";

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

// Writes `text` to `file` whole or not at all.
void write_text(const fs::path& file, const std::string& text) {
    if (!file.parent_path().empty()) fs::create_directories(file.parent_path());
    const fs::path temporary = file.parent_path() / ("." + file.filename().string() + ".partial");
    {
        std::ofstream out(temporary, std::ios::binary);
        out << text;
        if (!out.flush()) throw std::runtime_error(file.string() + ": cannot be written");
    }
    fs::rename(temporary, file);
}

CaseStatus status_from(const std::string& s, const std::string& file) {
    for (CaseStatus c : {CaseStatus::Pass, CaseStatus::Warn, CaseStatus::Fail, CaseStatus::Updated}) {
        if (s == status_name(c)) return c;
    }
    throw std::runtime_error(file + ": results[].status: unknown status '" + s + "'");
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
    json results = json::array();
    for (const CaseResult& r : run.results) {
        results.push_back({{"name", r.name}, {"index", r.index}, {"status", status_name(r.status)}, {"message", r.message},
                           {"pixels", r.pixels}, {"failing", r.failing}, {"warning", r.warning}, {"max_steps", r.max_steps},
                           {"seconds", r.seconds}, {"expected", fs::absolute(r.expected).string()},
                           {"actual", r.actual.empty() ? "" : fs::absolute(r.actual).string()},
                           {"diff", r.diff.empty() ? "" : fs::absolute(r.diff).string()}});
    }
    const json doc = {{"format", kFragmentFormat}, {"suite", run.suite},         {"shard", run.shard},
                      {"shards", run.shards},      {"suite_cases", run.suite_cases}, {"results", results}};
    write_text(file, doc.dump(1) + "\n");
}

SuiteRun merge_fragments(const std::vector<fs::path>& files) {
    SuiteRun merged;
    std::map<int, std::string> shards_seen;
    for (const fs::path& file : files) {
        const std::string name = file.string();
        std::ifstream in(file);
        if (!in) throw std::runtime_error(name + ": cannot be read");
        json doc;
        try {
            doc = json::parse(in);
            if (doc.value("format", "") != kFragmentFormat) throw std::runtime_error("format: not " + std::string(kFragmentFormat));
            const std::string suite = doc.at("suite").get<std::string>();
            const int shard = doc.at("shard").get<int>(), shards = doc.at("shards").get<int>();
            const std::size_t cases = doc.at("suite_cases").get<std::size_t>();
            if (shards_seen.empty()) {
                merged.suite = suite, merged.shards = shards, merged.suite_cases = cases;
            } else if (suite != merged.suite || shards != merged.shards || cases != merged.suite_cases) {
                throw std::runtime_error("suite, shards or suite_cases: not those of " + files.front().string());
            }
            if (shard < 1 || shard > shards) throw std::runtime_error("shard: " + std::to_string(shard) + " is not within 1.." + std::to_string(shards));
            if (const auto [it, added] = shards_seen.emplace(shard, name); !added) {
                throw std::runtime_error("shard " + std::to_string(shard) + " is also " + it->second);
            }
            for (const json& j : doc.at("results")) {
                CaseResult r;
                r.name = j.at("name").get<std::string>();
                r.index = j.at("index").get<std::size_t>();
                r.status = status_from(j.at("status").get<std::string>(), name);
                r.message = j.at("message").get<std::string>();
                r.pixels = j.at("pixels").get<long long>(), r.failing = j.at("failing").get<long long>();
                r.warning = j.at("warning").get<long long>(), r.max_steps = j.at("max_steps").get<int>();
                r.seconds = j.at("seconds").get<double>();
                r.expected = j.at("expected").get<std::string>();
                r.actual = j.at("actual").get<std::string>(), r.diff = j.at("diff").get<std::string>();
                merged.results.push_back(std::move(r));
            }
        } catch (const json::exception& e) {
            throw std::runtime_error(name + ": not a report fragment: " + e.what());
        } catch (const std::runtime_error& e) {
            throw std::runtime_error(name + ": " + e.what());
        }
    }
    if (int(shards_seen.size()) != merged.shards) {
        std::string missing;
        for (int k = 1; k <= merged.shards; ++k) {
            if (!shards_seen.count(k)) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
        }
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
    write_text(file, x);
}

void write_html(const SuiteRun& run, const fs::path& folder) {
    fs::create_directories(folder / "images");
    // The images are copied beside the page, so that it stays whole when the run's folder goes.
    auto image = [&](const fs::path& file, const CaseResult& r, const char* what) -> std::string {
        std::error_code ec;
        if (file.empty() || !fs::exists(file, ec)) return "<td class=\"none\">-</td>";
        const std::string name = r.name + "." + what + ".png";
        fs::copy_file(file, folder / "images" / name, fs::copy_options::overwrite_existing);
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
    write_text(folder / "index.html", h);
}

}  // namespace qs
