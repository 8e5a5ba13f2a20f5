// Error types with the exit codes the CLI promises: 2 for bad input (nothing computed),
// 3 for a diverging run (everything written so far is kept).
#pragma once
#include <stdexcept>
#include <string>

namespace slamsph {

// Bad case file or command line. Message names file, line and key.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A run that diverged: NaN, particle out of the domain, time step collapse.
class DivergenceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace slamsph
