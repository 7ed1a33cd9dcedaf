// libFuzzer target: the trajectory-file reader of check-trajectory (harness/trajectories/trajectory_reader.hpp).
// Any input must either be read or raise TrajectoryError; a trajectory that is read must be
// usable (at least two rows, times increasing, every value finite, Pi(0) not zero).
#include "harness/trajectories/trajectory_reader.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

void require(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz_trajectory: accepted a trajectory that %s\n", what);
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  // The first byte chooses the command-line parameters that accompany the file.
  gm::harness::TrajectoryParams params;
  const std::uint8_t mode = data[0];
  params.allow_nonphysical = mode & 1;
  if (mode & 2) params.system = "rigid_body";
  if (mode & 4) params.inertia = std::array<std::string, 3>{"2", "1.5", "1"};
  if (mode & 8) params.step = "0.1";
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    const auto tr = gm::harness::parse_trajectory(text, "fuzz.txt", params);
    require(tr.rows.size() >= 2, "has fewer than two rows");
    for (std::size_t i = 0; i < tr.rows.size(); ++i) {
      const auto& r = tr.rows[i];
      require(std::isfinite(r.t), "has a non-finite time");
      require(i == 0 || r.t > tr.rows[i - 1].t, "has times that do not increase");
      for (double v : r.Pi) require(std::isfinite(v), "has a non-finite Pi");
      for (double v : r.O) require(std::isfinite(v), "has a non-finite O");
    }
    const auto& p = tr.rows.front().Pi;
    require(p[0] != 0 || p[1] != 0 || p[2] != 0, "starts at rest");
    require(tr.step > 0, "has a step that is not positive");
  } catch (const gm::harness::TrajectoryError&) {}
  return 0;
}
