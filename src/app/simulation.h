// The run driver: one Simulation owns a case's state and runs it. Its parts each have one
// job (docs/architecture.md):
//   app/case_builder.h      case → particle sets, contact and ghost layout, parameters
//   app/fsi_stepper.h       one coupled step: rate operators in a fixed order, Δt, integrator
//   app/dual_time_stepping.h  bodies sub-cycled inside the fluid step (spec §6)
//   app/recorder.h          CSV/VTK/summary, probes, peak and impulse, next output times
// Nothing is global.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "app/fsi_stepper.h"
#include "app/probes.h"
#include "app/run_options.h"
#include "core/parallel.h"
#include "io/case_config.h"

namespace slamsph {

class Simulation {
 public:
  Simulation(CaseConfig config, const RunOptions& options);
  ~Simulation();

  // One fluid step (with the bodies sub-cycled inside it). Throws DivergenceError.
  void step() { stepper_->step(); }
  // Tests: how small bodies' sub-steps and the water's pass are scheduled (app/fsi_stepper.h).
  void set_beside_schedule(BesideSchedule s) { stepper_->set_beside_schedule(s); }
  void set_kick_in_pass(bool on) { stepper_->set_kick_in_pass(on); }
  long beside_advances() const { return stepper_->beside_advances(); }
  long beside_passes_redone() const { return stepper_->beside_passes_redone(); }
  // The whole run with outputs; returns the process exit code (0 ok, 3 diverged).
  int run();
  // After run(): true if the run reached end_time (not diverged, not stopped early).
  bool completed() const { return completed_; }
  // Makes run() continue from a checkpoint of this case (app/checkpoint.h) in place, in
  // the output folder it was written to. The checkpoint is read and checked by run().
  void resume_from(std::string checkpoint_path) { resume_from_ = std::move(checkpoint_path); }

  double time() const { return stepper_->time(); }
  long steps() const { return stepper_->steps(); }
  const CaseConfig& config() const { return cfg_; }
  const FluidParticles& fluid() const { return stepper_->system().fluid; }
  FluidParticles& fluid() { return stepper_->system().fluid; }
  const std::vector<SolidBody>& bodies() const { return stepper_->system().bodies; }
  std::vector<SolidBody>& bodies() { return stepper_->system().bodies; }
  const ContactParticles& contact() const { return stepper_->system().contact; }
  BodyLoad body_load(std::size_t b) const { return stepper_->body_load(b); }
  long leaked_particles() const { return stepper_->leaked_particles(); }
  // Set-up warnings for this case (app/setup_warnings.h), computed once at construction.
  const std::vector<std::string>& warnings() const { return warnings_; }
  const StepLimit& last_step_limit() const { return stepper_->last_step_limit(); }
  long steps_limited_by(StepLimiter l) const { return stepper_->steps_limited_by(l); }
  long solid_substeps() const { return stepper_->solid_substeps(); }
  const FsiStepper& stepper() const { return *stepper_; }
  // Linear momentum of fluid + non-fixed bodies [kg m/s per m], with the impulse the fluid
  // already gave up that a sub-cycled body has still to receive (SolidBody::impulse_due).
  Vec2 total_momentum() const;
  double probe_value(std::size_t k) const;  // current value of probe k (first column)

 private:
  CaseConfig cfg_;
  RunOptions opt_;
  Executor exec_;
  std::vector<std::string> warnings_;
  std::unique_ptr<FsiStepper> stepper_;
  std::unique_ptr<ProbeSet> probes_;
  std::string resume_from_;  // checkpoint to continue from ("" = a fresh run)
  bool completed_ = false;
};

}  // namespace slamsph
