#include "harness/portrait.hpp"

#include "harness/verdict_io.hpp"

namespace gm::harness {

std::vector<PortraitTask> portrait_task_list(const SubjectSet&, const CheckConfig&) { return {}; }

Verdict portrait_from_task(const PortraitTask& task, const TaskResult& result) {
  Verdict v;
  v.property = "portrait";
  v.integrator = task.integrator;
  v.scalar = task.scalar;
  if (result.status == TaskResult::Status::Ok) {
    auto vs = verdicts_from_string(result.payload);
    if (!vs.empty()) return vs.front();
  }
  v.outcome = Outcome::Error;
  v.message = result.detail;
  return v;
}

}  // namespace gm::harness
