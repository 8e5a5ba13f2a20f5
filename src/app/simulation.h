// The run driver: builds particles from a case, advances fluid and bodies with dual time
// stepping (spec §6), couples them through the Riemann contact (spec §4) and writes the
// outputs. One Simulation owns all state; nothing is global.
//
// Time integration (stated, spec §2 "a second-order integrator"): kick–drift–kick
// leapfrog for the fluid with one fused rate evaluation per step,
//   v+ = v + dt/2 a_n,  rho+ = rho + dt/2 drho_n,  x_n+1 = x_n + dt v+,
//   rates a_n+1, drho_n+1 evaluated at (x_n+1, v+ + dt/2 a_n, rho+ + dt/2 drho_n),
//   v_n+1 = v+ + dt/2 a_n+1,  rho_n+1 = rho+ + dt/2 drho_n+1.
// Bodies advance over the same [t_n, t_n+1] with the fluid force of the last evaluation
// held constant (sub-cycled by their own stable step when dual time stepping is on) and
// are then corrected for the new force (coupling/fluid_force_correction.h).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "app/run_options.h"
#include "core/kernel.h"
#include "core/parallel.h"
#include "coupling/contact_particles.h"
#include "coupling/ghost_layers.h"
#include "coupling/interaction_lists.h"
#include "fluid/fluid_particles.h"
#include "fluid/tait_eos.h"
#include "io/case_config.h"
#include "solid/solid_body.h"

namespace slamsph {

struct StepLimit {
  double dt = 0.0;
  std::string limiter;  // "fluid acoustic CFL", "fluid acceleration", "solid CFL (body b)", ...
};

struct BodyLoad {
  Vec2 total;    // fluid force on the body [N/m]
  Vec2 viscous;  // its viscous part [N/m]
};

class Simulation {
 public:
  Simulation(CaseConfig config, const RunOptions& options);
  ~Simulation();

  // One fluid step (with the bodies sub-cycled inside it). Throws DivergenceError.
  void step();
  // The whole run with outputs; returns the process exit code (0 ok, 3 diverged).
  int run();

  double time() const { return time_; }
  long steps() const { return steps_; }
  const CaseConfig& config() const { return cfg_; }
  const FluidParticles& fluid() const { return fluid_; }
  const std::vector<SolidBody>& bodies() const { return bodies_; }
  std::vector<SolidBody>& bodies() { return bodies_; }
  FluidParticles& fluid() { return fluid_; }
  const ContactParticles& contact() const { return contact_; }
  BodyLoad body_load(std::size_t b) const { return loads_[b]; }
  long leaked_particles() const { return leaked_; }
  // Set-up warnings for this case (app/setup_warnings.h), computed once at construction.
  const std::vector<std::string>& warnings() const { return warnings_; }
  const StepLimit& last_step_limit() const { return limit_; }
  long solid_substeps() const { return solid_substeps_; }
  // Linear momentum of fluid + non-fixed bodies [kg m/s per m].
  Vec2 total_momentum() const;
  double probe_value(std::size_t k) const;  // current value of probe k (first column)

 private:
  void build_bodies();
  void build_fluid();
  void build_contact();
  void attach_probes();
  void gather_contact();
  void evaluate_rates();
  StepLimit compute_step() const;
  void check_state() const;
  std::vector<double> probe_row() const;
  std::vector<std::string> probe_headers() const;
  void write_frame(class VtkSeries& vtk) const;

  CaseConfig cfg_;
  RunOptions opt_;
  Executor exec_;
  Kernel kernel_f_, kernel_c_;
  TaitEos eos_;
  FluidParticles fluid_;
  std::vector<SolidBody> bodies_;
  std::vector<std::vector<Vec2>> ref_normals_;
  std::vector<std::size_t> contact_offset_;  // first contact index of each body
  struct Ghost {
    std::uint32_t body;
    GhostSpec spec;
  };
  std::vector<Ghost> ghosts_;  // stored after all real contact particles
  ContactParticles contact_;
  std::unique_ptr<InteractionLists> lists_;
  std::vector<BodyLoad> loads_;
  struct AttachedProbe {
    std::size_t body = 0, particle = 0;
  };
  std::vector<AttachedProbe> attached_;  // per probe (body probes only)
  double time_ = 0.0;
  long steps_ = 0;
  long solid_substeps_ = 0;
  long leaked_ = 0;
  std::vector<std::string> warnings_;
  StepLimit limit_;
  std::vector<std::vector<Vec2>> f_old_;  // step() scratch: fluid force before the step
};

}  // namespace slamsph
