#include "core/parallel.h"

#include <omp.h>
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <thread>

namespace slamsph {

Executor::Executor(int threads) : threads_(std::max(1, threads)) {}

int Executor::team_rank() {
  return omp_get_thread_num();
}
int Executor::team_size() {
  return omp_get_num_threads();
}

void Team::barrier() const {
  if (size_ < 2) return;
  if (rank_ == 0) barriers_->fetch_add(1, std::memory_order_relaxed);
#pragma omp barrier
}

int Executor::hardware_threads() {
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

int Executor::affinity_threads() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) != 0) return 0;
  return CPU_COUNT(&set);
}

int Executor::env_threads() {
  // OMP_NUM_THREADS may be a list ("4,2" for nested levels); the first entry is ours.
  const char* s = std::getenv("OMP_NUM_THREADS");
  if (!s) return 0;
  char* end = nullptr;
  const long n = std::strtol(s, &end, 10);
  if (end == s || (*end != '\0' && *end != ',') || n < 1 || n > kMaxThreads) return 0;
  return static_cast<int>(n);
}

int Executor::default_threads() {
  if (const int n = env_threads(); n > 0) return n;
  if (const int n = affinity_threads(); n > 0) return n;
  return hardware_threads();
}

void Executor::use_passive_waiting(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") || std::getenv("GOMP_SPINCOUNT")) return;
  // Under valgrind (its preload library is in LD_PRELOAD) an exec would leave the tool and
  // run natively; callgrind counts do not depend on the wait policy anyway.
  const char* preload = std::getenv("LD_PRELOAD");
  if (preload && std::strstr(preload, "vgpreload")) return;
  if (setenv("OMP_WAIT_POLICY", "passive", 1) != 0) return;
  execv("/proc/self/exe", argv);
  // Only reached if exec failed (no /proc): undo, so a child process sees what we saw.
  unsetenv("OMP_WAIT_POLICY");
}

std::string Executor::wait_policy() {
  if (const char* v = std::getenv("OMP_WAIT_POLICY")) return std::string("OMP_WAIT_POLICY=") + v;
  if (const char* v = std::getenv("GOMP_SPINCOUNT")) return std::string("GOMP_SPINCOUNT=") + v;
  return "libgomp default";
}

}  // namespace slamsph
