#pragma once
// A shader_test's [vertex data]: a header of columns, each "NAME[INDEX]/GL_TYPE/GLSL_TYPE/COLUMN"
// (piglit's tests/util/piglit-vbo.cpp), then one row per vertex. Each column feeds a generic
// vertex attribute as glVertexAttribPointer (float attributes: integers converted, not
// normalized) or glVertexAttribIPointer (integer attributes) would; its values are kept as the
// 32-bit words the attribute reads, with GL's defaults (0, 0, 0, 1) for the components a column
// lacks.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "piglit/shader_test.h"

namespace qs::piglit {

enum class AttributeKind { Float, Int, Uint, Double };

struct VertexColumn {
    std::string name;        // the attribute's name (without [INDEX]), or its location as digits
    int array_index = 0;     // NAME[INDEX]
    std::string data_type;   // byte, ubyte, short, ushort, int, uint, half, float, double
    AttributeKind kind = AttributeKind::Float;  // how the shader reads it (the GLSL type's scalar)
    int rows = 1;            // components per vertex (a matrix column's rows)
    int columns = 1;         // of a matrix type
    int matrix_column = 0;   // which of the matrix's columns this is
    int line = 0;
};

struct VertexData {
    std::vector<VertexColumn> columns;
    // values[c][v]: column c's attribute value for vertex v, four words.
    std::vector<std::vector<std::array<std::uint32_t, 4>>> values;
    int vertices = 0;
};

// Throws ShaderTestError (FILE:LINE: ...) for a malformed header or row.
VertexData parse_vertex_data(const std::string& file, const std::vector<Line>& lines);

}  // namespace qs::piglit
