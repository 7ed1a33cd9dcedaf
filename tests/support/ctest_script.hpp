// Each test executable declares its own ctest tests: after a build, `<exe> --ctest-script FILE`
// writes one add_test per GoogleTest case with the labels returned by `labels_for`
// (scalar, spec kind and section, reference or negative control, ...), so `ctest -L exact` or
// `ctest -L algebraic` select exactly what they say. The file is written atomically.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace gm::testing_support {

// Labels for the GoogleTest case "suite.name".
using LabelFn = std::function<std::vector<std::string>(const std::string& suite, const std::string& name)>;

// If argv holds "--ctest-script FILE", writes the script for all registered tests and returns
// true (the caller then exits); otherwise returns false.
bool maybe_write_ctest_script(int argc, char** argv, const LabelFn& labels_for, int timeout_seconds = 300);

}  // namespace gm::testing_support
