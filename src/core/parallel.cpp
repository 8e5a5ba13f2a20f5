#include "core/parallel.h"

#include <sched.h>

#include <algorithm>
#include <cstdlib>
#include <thread>

namespace slamsph {

Executor::Executor(int threads) : threads_(std::max(1, threads)) {}

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

}  // namespace slamsph
