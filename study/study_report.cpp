// report.html: one file that holds every image and plot itself (as data: URIs), so that it can
// be mailed or archived alone.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "files/output_file.h"
#include "files/temporary_file.h"
#include "render/reference_process.h"
#include "scenes/base64.h"
#include "study/study.h"
#include "study/study_csv.h"

namespace qs::study {

namespace fs = std::filesystem;

namespace {

using Row = std::map<std::string, std::string>;

std::string escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&#39;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

double value(const Row& r, const std::string& column) { return std::strtod(r.at(column).c_str(), nullptr); }

std::string format(const char* f, double v) {
    if (std::isnan(v)) return "-";
    char s[64];
    std::snprintf(s, sizeof s, f, v);
    return s;
}

// The modes nothing beats on both time and RMS error against the truth; an error within 1% of a
// faster mode's is no improvement.
std::vector<std::string> pareto_front(std::vector<const Row*> rows) {
    std::sort(rows.begin(), rows.end(), [](const Row* a, const Row* b) {
        return std::pair(value(*a, "ms"), value(*a, "rms_vs_truth")) <
               std::pair(value(*b, "ms"), value(*b, "rms_vs_truth"));
    });
    std::vector<std::string> front;
    double best = INFINITY;
    for (const Row* r : rows) {
        if (value(*r, "rms_vs_truth") < 0.99 * best) front.push_back(r->at("mode")), best = value(*r, "rms_vs_truth");
    }
    return front;
}

// An image file as a data: URI; empty when there is none.
std::string data_uri(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return {};
    const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    return "data:image/png;base64," + base64(bytes);
}

std::string figure(const fs::path& root, const std::string& relative, const std::string& caption) {
    if (relative.empty()) return {};
    return "<figure><img class='px' src='" + data_uri(root / relative) + "' alt='" + escape(caption) +
           "'><figcaption>" + escape(caption) + "</figcaption></figure>";
}

// Draws plots/CASE.png for each of `cases` from its plots/CASE.csv with python3-matplotlib;
// returns why not, or empty. The script draws into a scratch folder; each plot is then copied
// into place by the output rule, as every output is.
std::string draw_plots(const fs::path& root, const std::vector<std::string>& cases) {
    const fs::path python = "/usr/bin/python3";
    const fs::path script = executable_folder().parent_path() / "share" / "quadshade" / "study" / "pareto_plot.py";
    if (!fs::exists(python)) return "no plots: /usr/bin/python3 is not installed";
    if (!fs::exists(script)) return "no plots: " + script.string() + " is missing (an incomplete installation?)";
    const ScratchFolder scratch(root / "plots");
    const fs::path log = scratch.path() / "pareto_plot.log";
    const int status =
        run_process({python.string(), script.string(), (root / "plots").string(), scratch.path().string()}, log);
    const std::string text = read_text(log);
    if (status == 3) return "no plots: " + text;
    if (status != 0)
        throw std::runtime_error(script.string() + " failed (exit " + std::to_string(status) + "): " + text);
    for (const std::string& c : cases) copy_to_output(scratch.path() / (c + ".png"), root / "plots" / (c + ".png"));
    return {};
}

// Float against double, and the undefined cases, on one view.
std::string stability_section(const fs::path& root, const Row& s, const Row* view) {
    std::ostringstream out;
    out << "<h3>Numerical stability</h3>\n<p>";
    if (view)
        out << "Coordinates offset by (" << escape(view->at("offset")) << "), time " << escape(view->at("time"))
            << ". ";
    out << "The fine rule's float image against its double one: RMS " << format("%.2e", value(s, "rms_float_vs_double"))
        << ", max " << format("%.3f", value(s, "max_float_vs_double")) << ", " << escape(s.at("over_1_255")) << " of "
        << escape(s.at("pixels")) << " pixels more than 1/255 apart (heat map full scale 8/255). ";
    if (s.at("undefined_pixels").empty()) {
        out << "Undefined cases not checked: " << escape(s.at("undefined_note")) << ".</p>\n";
    } else {
        out << "Undefined GLSL cases the colour depends on, in " << escape(s.at("undefined_pixels"))
            << " pixels: NaN produced " << escape(s.at("nan")) << ", division by zero "
            << escape(s.at("division_by_zero")) << ", a built-in outside its domain " << escape(s.at("domain"))
            << ", integer overflow " << escape(s.at("integer_overflow"))
            << " (the mask: red NaN, green division by zero, blue outside the domain, grey integer overflow).</p>\n";
    }
    out << "<div>" << figure(root, s.at("float_image"), "float") << figure(root, s.at("double_image"), "double")
        << figure(root, s.at("heat_image"), "|float - double|") << figure(root, s.at("mask_image"), "undefined cases")
        << "</div>\n";
    return out.str();
}

// The derivatives of the inputs, or of the expressions the study names, under each rule against
// the analytic ones: a table, then per input or expression the analytic map and each rule's map
// and heat map.
std::string derivative_section(const fs::path& root, const std::vector<Row>& rows) {
    if (rows.empty()) return {};
    std::ostringstream out;
    out << "<h3>Derivative maps</h3>\n<p>dFdx and dFdy of each input, or of each expression named with "
           "--derivatives-of (evaluated in the shader's GLSL where its main ends), under each quad rule against the "
           "analytic partials (Dual2), over the covered pixels; in brackets, relative to the RMS of the analytic "
           "gradient. Maps: dFdx red, dFdy green, mid-grey 0; heat maps full scale a quarter of the largest analytic "
           "derivative.</p>\n"
           "<table><tr><th>value</th><th>rule</th><th>RMS dFdx error</th><th>max dFdx error</th><th>RMS dFdy error</th>"
           "<th>max dFdy error</th><th>analytic RMS</th></tr>\n";
    for (const Row& d : rows) {
        const double scale = value(d, "analytic_rms");
        auto cell = [&](const char* column) {
            const double v = value(d, column);
            return format("%.2e", v) + (scale > 0 ? " (" + format("%.1e", v / scale) + ")" : "");
        };
        out << "<tr><td class='l'>" << escape(d.at("input")) << "</td><td class='l'>" << escape(d.at("rule"))
            << "</td><td>" << cell("rms_dx") << "</td><td>" << cell("max_dx") << "</td><td>" << cell("rms_dy")
            << "</td><td>" << cell("max_dy") << "</td><td>" << format("%.2e", scale) << "</td></tr>\n";
    }
    out << "</table>\n";
    std::string input;
    for (const Row& d : rows) {
        if (d.at("input") != input) {
            input = d.at("input");
            out << (&d == &rows.front() ? "" : "</div>") << "<div><b>" << escape(input) << "</b><br>"
                << figure(root, d.at("analytic_image"), "analytic (Dual2)");
        }
        out << figure(root, d.at("map_image"), d.at("rule"))
            << figure(root, d.at("heat_image"), "|" + d.at("rule") + " - analytic|");
    }
    out << "</div>\n";
    return out.str();
}

// The study's tables, grouped by case (a shader on a view), in the order the cases first appear.
using Case = std::pair<std::string, std::string>;
struct Study {
    std::vector<Row> rows;                           // study.csv: one per mode and case
    std::vector<Case> cases;
    std::map<Case, std::vector<const Row*>> of_case;  // rows of each case
    std::map<Case, Row> views;                        // views.csv
    std::map<Case, Row> stable;                       // stability.csv, where measured
    std::map<Case, std::vector<Row>> maps;            // derivatives.csv, where measured
    std::map<Case, std::vector<std::string>> fronts;  // the modes on each case's Pareto front
    std::map<Case, std::string> plot_names;           // named as the case's images' folder is
};

Study read_study(const fs::path& root) {
    Study st;
    st.rows = read_csv(root / "study.csv");
    for (Row& v : read_csv(root / "views.csv")) st.views[{v.at("shader"), v.at("view")}] = v;
    for (const Row& r : st.rows) {
        const Case key{r.at("shader"), r.at("view")};
        if (!st.of_case.count(key)) st.cases.push_back(key);
        st.of_case[key].push_back(&r);
    }
    for (const Case& key : st.cases) {
        st.fronts[key] = pareto_front(st.of_case[key]);
        st.plot_names[key] = fs::path(st.of_case[key].front()->at("image")).parent_path().filename().string();
    }
    if (fs::exists(root / "stability.csv")) {
        for (Row& s : read_csv(root / "stability.csv")) st.stable[{s.at("shader"), s.at("view")}] = std::move(s);
    }
    if (fs::exists(root / "derivatives.csv")) {
        for (Row& d : read_csv(root / "derivatives.csv")) st.maps[{d.at("shader"), d.at("view")}].push_back(std::move(d));
    }
    return st;
}

// Each case's points for the plot script, then the plots; what draw_plots says when it drew none.
std::string plot_cases(const fs::path& root, Study& st) {
    make_output_folder(root / "plots", FolderLink::Refused);
    std::vector<std::string> plotted;
    for (const Case& key : st.cases) {
        const std::vector<std::string>& front = st.fronts[key];
        std::string points = csv_line({"case", "mode", "group", "ms", "rms_vs_truth", "front"});
        for (const Row* r : st.of_case[key]) {
            const bool on = std::count(front.begin(), front.end(), r->at("mode")) > 0;
            points += csv_line({key.first + ", " + key.second, r->at("mode"), r->at("group"), r->at("ms"),
                                r->at("rms_vs_truth"), on ? "1" : "0"});
        }
        write_output(root / "plots" / (st.plot_names[key] + ".csv"), points);
        plotted.push_back(st.plot_names[key]);
    }
    return draw_plots(root, plotted);
}

// A case's table of modes, with the truth's and llvmpipe's images beside.
std::string modes_table(const fs::path& root, const std::vector<const Row*>& rs, const std::vector<std::string>& front) {
    std::ostringstream out;
    out << "<table><tr><th>mode</th><th>group</th><th>shader</th><th>ms (range)</th><th>RMS vs llvmpipe</th>"
           "<th>max vs llvmpipe</th><th>RMS vs truth</th><th>max vs truth</th></tr>\n";
    for (const Row* r : rs) {
        const bool on = std::count(front.begin(), front.end(), r->at("mode")) > 0;
        out << "<tr" << (on ? " class='front'" : "") << "><td class='l'>" << escape(r->at("mode"))
            << "</td><td class='l'>" << escape(r->at("group")) << "</td><td class='l'>" << escape(r->at("variant"))
            << "</td><td>" << format("%.3f", value(*r, "ms")) << " (" << format("%.3f", value(*r, "ms_min")) << "-"
            << format("%.3f", value(*r, "ms_max")) << ")</td><td>" << format("%.2e", value(*r, "rms_vs_llvmpipe"))
            << "</td><td>" << format("%.3f", value(*r, "max_vs_llvmpipe")) << "</td><td>"
            << format("%.2e", value(*r, "rms_vs_truth")) << "</td><td>" << format("%.3f", value(*r, "max_vs_truth"))
            << "</td></tr>\n";
    }
    out << "</table>\n<div>" << figure(root, rs.front()->at("truth_image"), "truth");
    std::vector<std::string> shown;
    for (const Row* r : rs) {
        const std::string& gl = r->at("llvmpipe_image");
        if (gl.empty() || std::count(shown.begin(), shown.end(), gl)) continue;
        shown.push_back(gl);
        out << figure(root, gl,
                      "OSMesa llvmpipe: " + r->at("variant") + " " +
                          fs::path(gl).stem().string().substr(fs::path(gl).stem().string().rfind('-') + 1));
    }
    out << "</div>\n";
    return out.str();
}

// A case's section: the view, the plot, the modes, stability and derivatives, every mode's image.
std::string case_section(const fs::path& root, Study& st, const Case& key, const std::string& no_plots) {
    std::ostringstream out;
    const std::vector<const Row*>& rs = st.of_case[key];
    const Row* v = st.views.count(key) ? &st.views[key] : nullptr;
    out << "<h2 id='" << escape(st.plot_names[key]) << "'>" << escape(key.first) << ", " << escape(key.second)
        << "</h2>\n<p>";
    if (v)
        out << escape(v->at("description")) << "; " << escape(v->at("width")) << "x" << escape(v->at("height"))
            << " pixels. Truth: " << escape(v->at("truth")) << ".";
    out << "</p>\n";
    if (no_plots.empty()) {
        out << "<img src='" << data_uri(root / "plots" / (st.plot_names[key] + ".png")) << "' alt='error against time'>\n";
    } else {
        out << "<p class='no-plot'>" << escape(no_plots) << "</p>\n";
    }
    out << modes_table(root, rs, st.fronts[key]);
    if (st.stable.count(key)) out << stability_section(root, st.stable[key], v);
    out << derivative_section(root, st.maps[key]);
    for (const Row* r : rs) {
        out << "<div><b>" << escape(r->at("mode")) << "</b><br>" << figure(root, r->at("image"), "quadshade")
            << figure(root, r->at("heat_image"), "|quadshade - truth|") << "</div>\n";
    }
    return out.str();
}

}  // namespace

void write_report(const fs::path& root) {
    Study st = read_study(root);
    const std::string no_plots = plot_cases(root, st);
    std::ostringstream out;
    out << "<!DOCTYPE html><html><head><meta charset='utf-8'><title>quadshade study</title><style>"
           "body{font-family:sans-serif;margin:1.5em;max-width:1400px}table{border-collapse:collapse;font-size:13px}"
           "td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}th{background:#eee}td.l{text-align:left}"
           "tr.front td{background:#fde8e8}img.px{image-rendering:pixelated;width:256px}"
           "figure{display:inline-block;margin:2px}figcaption{font-size:11px;text-align:center}</style></head><body>\n"
           "<h1>quadshade study: error against run time</h1>\n"
           "<p>Each mode renders the shader on each view, timed (median of the frames, their range in brackets), "
           "and is measured over RGB in [0, 1] against the truth (each view says which: the shader's unfiltered "
           "variant where it names one, else the shader itself, supersampled in double and box-filtered) and "
           "against OSMesa llvmpipe running the same GLSL (supersampled modes: llvmpipe supersampled alike). Rows "
           "on the Pareto front (nothing is both faster and more accurate) are shaded. Heat maps show "
           "|mode - truth|, full scale 0.25.</p>\n"
           "<p id='image-check'>images: not checked</p>\n<ul>";
    for (const auto& [shader, view] : st.cases) {
        out << "<li><a href='#" << escape(st.plot_names[{shader, view}]) << "'>" << escape(shader) << ", " << escape(view)
            << "</a></li>";
    }
    out << "</ul>\n";
    for (const Case& key : st.cases) out << case_section(root, st, key, no_plots);
    // Tells a headless browser (and a reader) whether every image loaded.
    out << "<script>\nwindow.addEventListener('load', () => {\n"
           "  const images = Array.from(document.images);\n"
           "  const ok = images.filter(i => i.complete && i.naturalWidth > 0).length;\n"
           "  document.getElementById('image-check').textContent = `images: ${ok}/${images.length} loaded`;\n"
           "});\n</script></body></html>\n";
    write_output(root / "report.html", out.str());
}

}  // namespace qs::study
