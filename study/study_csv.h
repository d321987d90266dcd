#pragma once
// The study's CSV files: RFC 4180 fields (quoted where they hold a comma, a quote or a line
// break), numbers in full precision.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace qs::study {

// study.csv's columns, in order.
inline const std::vector<std::string> kStudyColumns = {"shader",
                                                       "view",
                                                       "mode",
                                                       "group",
                                                       "variant",
                                                       "ms",
                                                       "ms_min",
                                                       "ms_max",
                                                       "rms_vs_llvmpipe",
                                                       "max_vs_llvmpipe",
                                                       "rms_vs_truth",
                                                       "max_vs_truth",
                                                       "width",
                                                       "height",
                                                       "image",
                                                       "llvmpipe_image",
                                                       "truth_image",
                                                       "heat_image",
                                                       "truth"};

// derivatives.csv's columns (derivative_maps.h).
inline const std::vector<std::string> kDerivativeColumns = {
    "shader", "view",         "input",   "rule",      "rms_dx",     "max_dx",        "rms_dy",
    "max_dy", "analytic_rms", "covered", "map_image", "heat_image", "analytic_image"};

// stability.csv's columns (stability.h).
inline const std::vector<std::string> kStabilityColumns = {
    "shader",           "view",   "rms_float_vs_double", "max_float_vs_double", "over_1_255",
    "pixels",           "undefined_pixels", "nan",       "division_by_zero",    "domain",
    "integer_overflow", "undefined_note",   "float_image", "double_image",      "heat_image",
    "mask_image"};

std::string csv_line(const std::vector<std::string>& fields);
std::string number(double v);  // "nan" for NaN

// The four CSV files' text, each from its header line: every study of a run adds its rows, and
// write_tables writes them whole once every study is done (so that a failed run leaves no table
// that reads as complete).
struct Tables {
    Tables();
    std::string study, views, derivatives, stability;
};

// study.csv, views.csv, derivatives.csv and stability.csv in `output`, by files/output_file.h's
// rule. Throws OutputError naming the file that could not be written.
void write_tables(const std::filesystem::path& output, const Tables& tables);

// The rows of a CSV file with a header line, each a map from column to field. Throws
// std::runtime_error naming the file and line of a malformed row.
std::vector<std::map<std::string, std::string>> read_csv(const std::filesystem::path& file);

}  // namespace qs::study
