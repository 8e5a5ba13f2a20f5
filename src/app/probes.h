// Point measurements of a run (the [[output.probe]] tables of a case): pressure at a point
// (Shepard kernel average), surge front, water height at x, largest fluid speed, pressure
// on a body surface and displacement of a body point. A body probe follows the body
// particle nearest to its start position.
#pragma once
#include <string>
#include <vector>

#include "app/fsi_stepper.h"
#include "io/case_config.h"

namespace slamsph {

class Executor;

class ProbeSet {
 public:
  // dx: the fluid spacing (half of it is a particle's extent for fronts and heights).
  ProbeSet(std::vector<ProbeConfig> probes, const std::vector<SolidBody>& bodies, double dx);

  // Column headers with units ("name [Pa]"); body_displacement gives two columns.
  std::vector<std::string> headers() const;
  // Current values, one per header.
  std::vector<double> row(const FsiStepper& st, const Executor& exec) const;
  // First column of probe k.
  double value(std::size_t k, const FsiStepper& st, const Executor& exec) const;

 private:
  struct Attached {
    std::size_t body = 0, particle = 0;
  };
  std::vector<ProbeConfig> probes_;
  std::vector<Attached> attached_;  // per probe (body probes only)
  double dx_;
};

}  // namespace slamsph
