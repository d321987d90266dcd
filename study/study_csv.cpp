#include "study/study_csv.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "files/output_file.h"

namespace qs::study {

std::string csv_line(const std::vector<std::string>& fields) {
    std::string line;
    for (std::size_t i = 0; i < fields.size(); ++i) {
        const std::string& f = fields[i];
        if (i) line += ',';
        if (f.find_first_of(",\"\n\r") == std::string::npos) {
            line += f;
            continue;
        }
        line += '"';
        for (char c : f) line += c == '"' ? std::string("\"\"") : std::string(1, c);
        line += '"';
    }
    return line + "\n";
}

std::string number(double v) {
    if (std::isnan(v)) return "nan";
    char s[32];
    std::snprintf(s, sizeof s, "%.9g", v);
    return s;
}

Tables::Tables()
    : study(csv_line(kStudyColumns)),
      views(csv_line({"shader", "view", "description", "width", "height", "truth", "offset", "time"})),
      derivatives(csv_line(kDerivativeColumns)),
      stability(csv_line(kStabilityColumns)) {}

void write_tables(const std::filesystem::path& output, const Tables& tables) {
    write_output(output / "study.csv", tables.study);
    write_output(output / "views.csv", tables.views);
    write_output(output / "derivatives.csv", tables.derivatives);
    write_output(output / "stability.csv", tables.stability);
}

namespace {

// The records of `text`: fields split on commas outside quotes, records on line breaks outside
// quotes.
std::vector<std::vector<std::string>> records(const std::string& text, const std::filesystem::path& file) {
    std::vector<std::vector<std::string>> out;
    std::vector<std::string> record;
    std::string field;
    bool quoted = false, any = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (quoted) {
            if (c == '"' && i + 1 < text.size() && text[i + 1] == '"')
                field += '"', ++i;
            else if (c == '"')
                quoted = false;
            else
                field += c;
        } else if (c == '"') {
            quoted = any = true;
        } else if (c == ',') {
            record.push_back(std::move(field)), field.clear(), any = true;
        } else if (c == '\n') {
            record.push_back(std::move(field)), field.clear();
            out.push_back(std::move(record)), record.clear(), any = false;
        } else if (c != '\r') {
            field += c, any = true;
        }
    }
    if (quoted) throw std::runtime_error(file.string() + ": a quoted field is not closed");
    if (any) record.push_back(std::move(field)), out.push_back(std::move(record));
    return out;
}

}  // namespace

std::vector<std::map<std::string, std::string>> read_csv(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error(file.string() + ": cannot read");
    std::stringstream s;
    s << in.rdbuf();
    const auto rows = records(s.str(), file);
    if (rows.empty()) throw std::runtime_error(file.string() + ": empty, no header line");
    std::vector<std::map<std::string, std::string>> out;
    for (std::size_t r = 1; r < rows.size(); ++r) {
        if (rows[r].size() != rows[0].size()) {
            throw std::runtime_error(file.string() + ": record " + std::to_string(r + 1) + " has " +
                                     std::to_string(rows[r].size()) + " fields, the header " +
                                     std::to_string(rows[0].size()));
        }
        std::map<std::string, std::string> row;
        for (std::size_t c = 0; c < rows[0].size(); ++c) row[rows[0][c]] = rows[r][c];
        out.push_back(std::move(row));
    }
    return out;
}

}  // namespace qs::study
