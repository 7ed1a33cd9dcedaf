// Hostile: a herd of its own threads that would read as a starved machine. A static initializer
// starts 24 threads (leaving the server room to fork the session a check runs in), pinned to one
// core, waking together for 20 ms every 0.1 s; Euler's equations (3.8) sleep and never return. Judged per task (the task the check
// waits on sleeps; the tree keeps more tasks runnable than its cores), the check is the code's
// TIMEOUT ("it starves itself"), never the machine's ERROR. vee, which is correct, still passes.
#include <geomech/student.hpp>

#include <chrono>
#include <sched.h>
#include <thread>
#include <vector>

using namespace gm;

namespace {

void wake_together(int core) {
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(core, &one);
  ::sched_setaffinity(0, sizeof one, &one);
  using Clock = std::chrono::steady_clock;
  for (;;) {
    const auto now = Clock::now().time_since_epoch();
    const auto period = std::chrono::milliseconds(100);
    std::this_thread::sleep_for(period - now % period);
    const auto start = Clock::now();
    while (Clock::now() - start < std::chrono::milliseconds(20)) {
    }
  }
}

// Only in the protocol server a check talks to (not while the suite compiles the file's pieces).
const int herd = [] {
  cpu_set_t mine;
  ::sched_getaffinity(0, sizeof mine, &mine);
  int core = 0;
  while (core < CPU_SETSIZE && !CPU_ISSET(core, &mine)) ++core;
  int started = 0;
  for (; started < 24; ++started) {
    try {
      std::thread(wake_together, core).detach();
    } catch (const std::exception&) {
      break;  // the sandbox allows no more
    }
  }
  return started;
}();

}  // namespace

struct Herd {
  template <class T>
  static Vec3<T> euler_3_8(const Vec3<T>& I, const Vec3<T>& Pi) {
    for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
    return Pi.cross(Vec3<T>(Pi.cwiseQuotient(I)));
  }
  template <class T>
  static Vec3<T> vee(const Mat3<T>& m) {
    return Vec3<T>(m(2, 1), m(0, 2), m(1, 0));
  }
};

GEOMECH_STUDENT(Herd);
