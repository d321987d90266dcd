#include "piglit/vertex_data.h"

#include <bit>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "piglit/numbers.h"

namespace qs::piglit {

namespace {

[[noreturn]] void error(const std::string& file, int line, const std::string& message) {
    throw ShaderTestError(file + ":" + std::to_string(line) + ": " + message);
}

struct DataType {
    const char* name;
    AttributeKind kind;  // of the old "NAME/TYPE/COUNT" syntax, where the GL type decides it
    bool integer;
};
constexpr DataType kDataTypes[] = {
    {"byte", AttributeKind::Int, true},    {"ubyte", AttributeKind::Uint, true}, {"short", AttributeKind::Int, true},
    {"ushort", AttributeKind::Uint, true}, {"int", AttributeKind::Int, true},    {"uint", AttributeKind::Uint, true},
    {"half", AttributeKind::Float, false}, {"float", AttributeKind::Float, false}, {"double", AttributeKind::Double, false},
};

// "vec3", "uvec2", "mat2x3", "float", ... or a count ("3"): kind, rows and columns.
bool parse_glsl_type(const std::string& t, AttributeKind data_kind, VertexColumn& c) {
    if (!t.empty() && std::isdigit(static_cast<unsigned char>(t[0]))) {
        if (t.size() != 1) return false;
        c.rows = t[0] - '0', c.columns = 1, c.kind = data_kind;
        return true;
    }
    struct Prefix {
        const char* name;
        AttributeKind kind;
        int shape;  // 0 scalar, 1 vector, 2 matrix
    };
    static constexpr Prefix kTypes[] = {
        {"int", AttributeKind::Int, 0},    {"uint", AttributeKind::Uint, 0},   {"float", AttributeKind::Float, 0},
        {"double", AttributeKind::Double, 0}, {"ivec", AttributeKind::Int, 1}, {"uvec", AttributeKind::Uint, 1},
        {"vec", AttributeKind::Float, 1},  {"dvec", AttributeKind::Double, 1}, {"mat", AttributeKind::Float, 2},
        {"dmat", AttributeKind::Double, 2},
    };
    for (const Prefix& p : kTypes) {
        const std::size_t n = std::strlen(p.name);
        if (t.compare(0, n, p.name) != 0) continue;
        const std::string rest = t.substr(n);
        c.kind = p.kind;
        if (p.shape == 0) {
            if (!rest.empty()) continue;
            c.rows = c.columns = 1;
            return true;
        }
        if (rest.empty() || !std::isdigit(static_cast<unsigned char>(rest[0]))) return false;
        const int first = rest[0] - '0';
        if (p.shape == 1) {
            if (rest.size() != 1) return false;
            c.rows = first, c.columns = 1;
            return true;
        }
        if (rest.size() == 1) {
            c.rows = c.columns = first;
            return true;
        }
        if (rest.size() != 3 || rest[1] != 'x' || !std::isdigit(static_cast<unsigned char>(rest[2]))) return false;
        c.columns = first, c.rows = rest[2] - '0';
        return true;
    }
    return false;
}

VertexColumn parse_column(const std::string& file, int line, const std::string& header) {
    const auto bad = [&](const std::string& why) {
        error(file, line, "[vertex data] column '" + header + "': " + why +
                              " (expected NAME[INDEX]/GL_TYPE/GLSL_TYPE/MATRIX_COLUMN)");
    };
    std::vector<std::string> parts;
    for (std::size_t at = 0;;) {
        const std::size_t slash = header.find('/', at);
        parts.push_back(header.substr(at, slash == std::string::npos ? std::string::npos : slash - at));
        if (slash == std::string::npos) break;
        at = slash + 1;
    }
    if (parts.size() < 3 || parts.size() > 4) bad("not three or four parts");
    VertexColumn c;
    c.line = line;
    c.name = parts[0];
    if (!c.name.empty() && c.name.back() == ']') {
        const std::size_t open = c.name.find('[');
        if (open == std::string::npos) bad("an array index without '['");
        c.array_index = std::atoi(c.name.c_str() + open + 1);
        c.name.resize(open);
    }
    if (c.name.empty()) bad("no attribute name");
    const DataType* type = nullptr;
    for (const DataType& t : kDataTypes) {
        if (parts[1] == t.name) type = &t;
    }
    if (!type) bad("unknown GL type '" + parts[1] + "'");
    c.data_type = type->name;
    if (!parse_glsl_type(parts[2], type->kind, c)) bad("unknown GLSL type '" + parts[2] + "'");
    if (parts.size() == 4) {
        char* end = nullptr;
        const long column = std::strtol(parts[3].c_str(), &end, 10);
        if (*end != '\0' || column < 0 || column > 3) bad("matrix column must be between 0 and 3");
        c.matrix_column = int(column);
    }
    if (c.rows < 1 || c.rows > 4) bad("rows must be between 1 and 4");
    if (c.columns < 1 || c.columns > 4) bad("columns must be between 1 and 4");
    if (c.kind != AttributeKind::Float && c.kind != AttributeKind::Double && !type->integer) {
        bad("an integer attribute needs an integer GL type");
    }
    return c;
}

// One value of column c from `s`, as the 32-bit word the attribute reads; advances s.
bool parse_datum(const VertexColumn& c, const char*& s, std::uint32_t& word) {
    char* end = nullptr;
    errno = 0;
    const std::string& t = c.data_type;
    if (t == "float" || t == "double" || t == "half") {
        const float v = t == "half" ? parse_half(s, &end) : parse_float(s, &end);
        if (end == s || errno == ERANGE) return false;
        s = end;
        word = std::bit_cast<std::uint32_t>(v);
        return true;
    }
    const bool is_unsigned = t[0] == 'u';
    long long value = 0;
    if (is_unsigned) {
        const unsigned long long u = std::strtoull(s, &end, 0);
        value = (long long)u;
        const unsigned long long max = t == "ubyte" ? 0xFFu : t == "ushort" ? 0xFFFFu : 0xFFFFFFFFu;
        if (end == s || errno == ERANGE || u > max) return false;
    } else {
        value = parse_integer(s, &end);  // an int's bits, as piglit's strtol_hex returns them
        const long long lo = t == "byte" ? -128 : t == "short" ? -32768 : INT32_MIN;
        const long long hi = t == "byte" ? 127 : t == "short" ? 32767 : INT32_MAX;
        if (end == s || value < lo || value > hi) return false;
    }
    s = end;
    // glVertexAttribPointer converts an integer to float without normalizing it.
    word = c.kind == AttributeKind::Float ? std::bit_cast<std::uint32_t>(is_unsigned ? float((unsigned long long)value)
                                                                                     : float(value))
                                          : std::uint32_t(value);
    return true;
}

}  // namespace

VertexData parse_vertex_data(const std::string& file, const std::vector<Line>& lines) {
    VertexData d;
    bool header = false;
    for (const Line& line : lines) {
        std::string text = line.text.substr(0, line.text.find('#'));
        bool blank = true;
        for (char ch : text) blank = blank && std::isspace(static_cast<unsigned char>(ch));
        if (blank) continue;
        if (!header) {
            header = true;
            for (std::size_t at = 0; at < text.size();) {
                if (std::isspace(static_cast<unsigned char>(text[at]))) {
                    ++at;
                    continue;
                }
                std::size_t end = at;
                while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end]))) ++end;
                d.columns.push_back(parse_column(file, line.number, text.substr(at, end - at)));
                at = end;
            }
            d.values.resize(d.columns.size());
            continue;
        }
        const char* s = text.c_str();
        for (std::size_t c = 0; c < d.columns.size(); ++c) {
            const VertexColumn& col = d.columns[c];
            std::array<std::uint32_t, 4> value{};
            const bool real = col.kind == AttributeKind::Float || col.kind == AttributeKind::Double;
            value[3] = real ? std::bit_cast<std::uint32_t>(1.0f) : 1u;
            for (int k = 0; k < col.rows; ++k) {
                if (!parse_datum(col, s, value[std::size_t(k)])) {
                    error(file, line.number, "[vertex data]: cannot read a " + col.data_type + " for column '" + col.name +
                                                 "' at '" + std::string(s) + "'");
                }
            }
            d.values[c].push_back(value);
        }
        ++d.vertices;
    }
    return d;
}

}  // namespace qs::piglit
