// Dam break (validation README §2): the surge front of a column of width a and height 2a
// against Martin & Moyce (1952) and Koshizuka & Oka (1996) for T <= 2.5 at CI resolution
// (a/dx = 25). The target, 10 % against Martin & Moyce, is met for T >= 1.97
// only: between T = 0.84 and 1.82 the inviscid front runs 11-16 % ahead of that
// experiment (whose gate took time to lift; at the same T it is 5-9 % ahead of Koshizuka
// & Oka). The bounds are the measured errors plus a margin (docs/validation.md).
#include <gtest/gtest.h>

#include <cmath>

#include "app/simulation.h"
#include "io/case_file.h"
#include "io/case_resolution.h"
#include "io/reference_curves.h"

using namespace slamsph;

TEST(DamBreak, SurgeFrontFollowsMartinMoyce) {
  CaseConfig cfg = load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/dam_break.toml");
  rescale_resolution(cfg, 0.02);
  const double a = 0.5, g = 9.81;
  const double t_end = 2.5 / std::sqrt(2 * g / a);
  cfg.numerics.end_time = t_end;
  Simulation sim(cfg, silent_options(2));
  std::vector<double> t{0.0}, front{sim.probe_value(0)};
  while (sim.time() < t_end) {
    sim.step();
    t.push_back(sim.time());
    front.push_back(sim.probe_value(0));
  }
  const SeriesError mm = front_error(t, front, a, g, martin_moyce_1952(), 2.5);
  const SeriesError ko = front_error(t, front, a, g, koshizuka_oka_1996(), 2.5);
  std::printf(
      "front error vs Martin & Moyce: max %.2f %% (at T = %.2f), rms %.2f %%; vs Koshizuka & Oka: "
      "max %.2f %%, rms %.2f %%\n",
      100 * mm.max_abs, mm.at, 100 * mm.rms, 100 * ko.max_abs, 100 * ko.rms);
  EXPECT_GE(mm.samples, 8u);
  EXPECT_LT(mm.max_abs, 0.18);
  EXPECT_LT(mm.rms, 0.12);
  EXPECT_LT(ko.max_abs, 0.13);
  // Late fronts (T >= 1.97) within the 10 % of Martin & Moyce.
  const FrontTable mm_table = martin_moyce_1952();
  FrontTable late{mm_table.name, {}, {}};
  for (std::size_t k = 0; k < mm_table.T.size(); ++k)
    if (mm_table.T[k] >= 1.97) late.T.push_back(mm_table.T[k]), late.Z.push_back(mm_table.Z[k]);
  const SeriesError mm_late = front_error(t, front, a, g, late, 2.5);
  std::printf("vs Martin & Moyce for 1.97 <= T <= 2.5: max %.2f %%\n", 100 * mm_late.max_abs);
  EXPECT_GE(mm_late.samples, 3u);
  EXPECT_LT(mm_late.max_abs, 0.10);
  EXPECT_EQ(sim.leaked_particles(), 0);
}
