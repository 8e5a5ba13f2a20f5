#include "core/parallel.h"

#include <omp.h>

#include <algorithm>

namespace slamsph {

Executor::Executor(int threads) : threads_(std::max(1, threads)) {}

int Executor::hardware_threads() {
  return omp_get_num_procs();
}

}  // namespace slamsph
