// One-line progress display on stderr, redrawn in place with '\r':
//   "t 0.0123/0.05 s  24.6%  1234 steps  456 steps/s  dt 1.2e-06 s  ETA 0:01:23"
// Redrawn at most every `min_interval` seconds of wall time (default 0.25 s, ~4 Hz).
// steps/s is measured since the previous redraw; the ETA extrapolates the average
// simulated-time rate since the first update(). The caller decides whether it is enabled
// (normally isatty(STDERR_FILENO)); when disabled it prints nothing. The clock and the
// output stream are injectable for tests.
#pragma once
#include <functional>
#include <iosfwd>
#include <string>

namespace slamsph {

class ProgressLine {
 public:
  using Clock = std::function<double()>;  // wall time in seconds, any origin

  ProgressLine(double end_time, bool enabled);
  ProgressLine(double end_time, bool enabled, Clock clock, std::ostream& out,
               double min_interval = 0.25);

  // For logs (stderr not a terminal): one plain line per redraw, ending in '\n', no '\r',
  // with the elapsed wall time, at most every `interval` seconds.
  void set_plain(double interval) {
    plain_ = true;
    min_interval_ = interval;
  }

  // Redraws if at least min_interval has passed since the last redraw (the first call
  // always draws).
  void update(double t, long steps, double dt);
  // Draws the final state (if anything was updated) and ends the line with '\n'.
  // Idempotent.
  void finish();

  // The text of one line (without '\r' and padding), for tests.
  std::string format(double t, long steps, double steps_per_s, double dt, double eta_seconds) const;

 private:
  void draw(double now);

  double end_time_;
  bool enabled_;
  Clock clock_;
  std::ostream* out_;
  double min_interval_;
  bool plain_ = false;
  bool started_ = false;
  bool finished_ = false;
  double t0_wall_ = 0.0, t0_sim_ = 0.0;
  double last_draw_wall_ = 0.0;
  long last_draw_steps_ = 0;
  double t_ = 0.0, dt_ = 0.0;
  long steps_ = 0;
  std::size_t last_len_ = 0;
};

// "h:mm:ss" (hours unbounded); "--:--:--" for a negative or non-finite duration.
std::string format_hms(double seconds);

}  // namespace slamsph
