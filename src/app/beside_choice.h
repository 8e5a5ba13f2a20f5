// Whether small bodies' sub-steps run beside the water's pair pass (app/fsi_stepper.h), from
// the wall times this run has measured: "in turn" the sub-steps (one thread) and then the
// pass (both threads), "beside" the two at once, one thread each, plus the pass again when a
// neighbour rebuild discards it. Beside wins when the sub-steps last about as long as the
// pass: the elastic gate of bench/elastic_gate_peer.toml (22 sub-steps per step of a
// 480-particle gate beside 2 240 water particles) takes 8.3 → 7.6 s on 2 threads; it loses
// when they are short, since the pass on one thread then sets the pace: the rubber cylinder
// of cases/elastic_cylinder_entry.toml (3 sub-steps per step beside 16 000 water particles)
// took 3.1 → 3.8 s (docs/validation.md §6 "Threads", session 16). The costs change over a
// run (the water spreads, a body slows down), so the choice is a running comparison.
//
// Either way the arithmetic is the same, in the same order (fsi_stepper.h): the choice, and
// so the clock, changes the speed, never the results.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>

namespace slamsph {

// Measured: BesideChoice decides (the command line's runs). Always / Never: every eligible
// advance beside the pass, or none (tests: the beside path, with the rebuilds that discard
// its pass, against one thread).
enum class BesideSchedule { Measured, Always, Never };

class BesideChoice {
 public:
  // Decisions spent on each way at the start, and again on the way not taken every
  // kRecheck decisions (the other way's costs may have changed).
  static constexpr std::uint32_t kProbe = 4;
  static constexpr std::uint32_t kRecheck = 256;

  // Whether the next eligible advance should run beside the pass.
  bool beside() const {
    if (in_turn_.count < kProbe) return false;
    if (beside_.count < kProbe) return true;
    const bool better = beside_.median() < in_turn_.median();
    // Every kRecheck decisions, kProbe decisions the other way.
    if (decisions_ % kRecheck >= kRecheck - kProbe) return !better;
    return better;
  }
  // The wall seconds of the sub-steps and the pass of one advance taken that way.
  void record(bool beside, double seconds) {
    (beside ? beside_ : in_turn_).add(seconds);
    ++decisions_;
  }
  double median_in_turn() const { return in_turn_.median(); }
  double median_beside() const { return beside_.median(); }

 private:
  // The median of the last kWindow samples: a run shares its machine, and one advance
  // preempted for milliseconds must not decide the next hundreds (a running mean did: the
  // gate then took the slower way in a third of its steps).
  static constexpr std::uint32_t kWindow = 15;
  struct Window {
    std::array<double, kWindow> last{};
    std::uint64_t count = 0;
    void add(double s) { last[count++ % kWindow] = s; }
    double median() const {
      const std::size_t n = count < kWindow ? count : kWindow;
      if (n == 0) return 0.0;
      std::array<double, kWindow> v = last;
      std::nth_element(v.begin(), v.begin() + n / 2, v.begin() + n);
      return v[n / 2];
    }
  };
  Window in_turn_, beside_;
  std::uint64_t decisions_ = 0;
};

}  // namespace slamsph
