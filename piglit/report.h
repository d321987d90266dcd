#pragma once
// What a run of many shader_tests reports: each test's line in piglit's words, the failing
// probes with expected and observed values, a summary by folder and by skip reason, and JUnit
// XML in the form piglit's own JUnit backend writes (classname piglit.FOLDER..., warn passes).

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "piglit/test_result.h"

namespace qs::piglit {

// The test's name: its path after the last "spec/" of piglit's trees (tests/spec,
// generated_tests/spec), without ".shader_test"; else the path as given, without it.
std::string test_name(const std::string& file);
// The folder a test is summed in: the first two parts of its name ("glsl-1.10/execution"), or
// its folder when the name has fewer.
std::string test_group(const std::string& file);

// "pass: NAME", "skip: NAME (reason)", ... and, for a test that did not pass, its message and
// probes, indented.
void print_result(std::FILE* out, const TestResult& r);
// The tables: per folder the count of each result, the totals, and the skips by reason.
void print_summary(std::FILE* out, const std::vector<TestResult>& results, double seconds);
// Throws std::runtime_error when the file cannot be written.
void write_junit(const std::filesystem::path& path, const std::vector<TestResult>& results);

}  // namespace qs::piglit
