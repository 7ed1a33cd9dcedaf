// The geomech tool's commands for where courses grade:
//   geomech autograder gradescope|prairielearn DIR --rubric FILE.json [check options] [--trusted]
//       writes an autograder (harness/class/autograder.hpp); the check options (--scalar, -p, --quick,
//       --timeout, ...) are those of `geomech check` and apply to every submission
//   geomech grade-submission gradescope|prairielearn --submission DIR --results FILE --config FILE
//       what the autograder runs for each submission: results.json in the platform's format
//   geomech class-html REPORT_DIR [--rubric FILE.json]
//       summary.html again from a class report folder's record (class-shard.json)
// Each runs from its CLI11 callback and leaves with its exit status through CLI::RuntimeError, as
// the golden commands do (golden/cli.hpp); an error is printed as "geomech: ..." with status 2.
#pragma once

namespace CLI {
class App;
}

namespace gm::harness {

void add_lecturer_commands(CLI::App& app);

}  // namespace gm::harness
