#include "core/parallel.h"

#include <algorithm>
#include <thread>

namespace slamsph {

Executor::Executor(int threads) : threads_(std::max(1, threads)) {}

int Executor::hardware_threads() {
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

}  // namespace slamsph
