// The harness tests' program: the tests of each room are in tests/harness/<room>/, as the harness's
// rooms are in harness/<room>/ (harness/README.md); this file holds their labels and main().
// Nothing here compiles a student's code; tests/example_tests.cpp does that.
#include "tests/support/ctest_script.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace gm::harness {
namespace {

std::vector<std::string> labels(const std::string& suite, const std::string&) {
  if (suite == "TrajectoryFiles") return {"meta", "harness", "bad-input"};
  if (suite == "Notebook") return {"meta", "harness", "notebook", "bad-input"};
  if (suite == "RemoteSubject" || suite == "ProtocolCodec") return {"meta", "harness", "protocol", "python"};
  if (suite == "Gradebook" || suite == "SourceCalls" || suite == "HtmlPage" || suite == "ClassRecord" ||
      suite == "Autograder")
    return {"meta", "harness", "lecturer"};
  return {"meta", "harness"};
}

}  // namespace
}  // namespace gm::harness

int main(int argc, char** argv) {
  if (gm::testing_support::maybe_write_ctest_script(argc, argv, gm::harness::labels)) return 0;
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
