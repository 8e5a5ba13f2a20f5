// Progress line on stderr; behaviour in progress_line.h.
#include "io/progress_line.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace slamsph {

std::string format_hms(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0) return "--:--:--";
  const long long s = std::llround(seconds);
  char buf[48];
  std::snprintf(buf, sizeof buf, "%lld:%02lld:%02lld", s / 3600, (s / 60) % 60, s % 60);
  return buf;
}

namespace {
double steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

ProgressLine::ProgressLine(double end_time, bool enabled)
    : ProgressLine(end_time, enabled, steady_seconds, std::cerr) {}

ProgressLine::ProgressLine(double end_time, bool enabled, Clock clock, std::ostream& out,
                           double min_interval)
    : end_time_(end_time),
      enabled_(enabled),
      clock_(std::move(clock)),
      out_(&out),
      min_interval_(min_interval) {}

std::string ProgressLine::format(double t, long steps, double steps_per_s, double dt,
                                 double eta_seconds) const {
  const double pct = end_time_ > 0.0 ? 100.0 * t / end_time_ : 0.0;
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "t %.4g/%.4g s  %5.1f%%  %ld steps  %.0f steps/s  dt %.3g s  ETA %s", t, end_time_,
                pct, steps, steps_per_s, dt, format_hms(eta_seconds).c_str());
  return buf;
}

void ProgressLine::update(double t, long steps, double dt) {
  if (!enabled_ || finished_) return;
  const double now = clock_();
  t_ = t;
  steps_ = steps;
  dt_ = dt;
  if (!started_) {
    started_ = true;
    t0_wall_ = now;
    t0_sim_ = t;
    last_draw_wall_ = now;
    last_draw_steps_ = steps;
    draw(now);
    return;
  }
  if (now - last_draw_wall_ >= min_interval_) draw(now);
}

void ProgressLine::draw(double now) {
  const double window = now - last_draw_wall_;
  double rate = 0.0;
  if (window > 0.0) {
    rate = static_cast<double>(steps_ - last_draw_steps_) / window;
  } else if (now > t0_wall_) {
    rate = static_cast<double>(steps_) / (now - t0_wall_);
  }
  double eta = -1.0;  // unknown
  const double elapsed = now - t0_wall_;
  if (t_ > t0_sim_ && elapsed > 0.0) eta = (end_time_ - t_) * elapsed / (t_ - t0_sim_);
  if (eta < 0.0 && t_ >= end_time_) eta = 0.0;
  const std::string line = format(t_, steps_, rate, dt_, eta);
  if (plain_) {
    *out_ << "progress: " << line << "  elapsed " << format_hms(elapsed) << '\n' << std::flush;
    last_draw_wall_ = now;
    last_draw_steps_ = steps_;
    return;
  }
  std::string padded = "\r" + line;
  if (line.size() < last_len_) padded.append(last_len_ - line.size(), ' ');
  *out_ << padded << std::flush;
  last_len_ = line.size();
  last_draw_wall_ = now;
  last_draw_steps_ = steps_;
}

void ProgressLine::finish() {
  if (!enabled_ || finished_) return;
  finished_ = true;
  if (!started_) return;
  draw(clock_());
  if (!plain_) *out_ << '\n' << std::flush;
}

}  // namespace slamsph
