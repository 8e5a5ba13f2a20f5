#include "app/end_time_override.h"

#include <algorithm>
#include <cstdio>

namespace slamsph {

std::vector<std::string> override_end_time(CaseConfig& cfg, double end_time) {
  cfg.numerics.end_time = end_time;
  std::vector<double>& snaps = cfg.output.snapshots;
  // The tolerance of the case check (io/case_parse.cpp): a snapshot at the end time itself,
  // written as a rounded decimal, is kept.
  const auto after = std::find_if(snaps.begin(), snaps.end(),
                                  [&](double t) { return !(t <= end_time * (1.0 + 1e-12)); });
  if (after == snaps.end()) return {};
  std::string dropped;
  for (auto it = after; it != snaps.end(); ++it) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%s%g", it == after ? "" : ", ", *it);
    dropped += buf;
  }
  char end[32];
  std::snprintf(end, sizeof end, "%g", end_time);
  const std::size_t n = static_cast<std::size_t>(snaps.end() - after);
  snaps.erase(after, snaps.end());
  std::string w = "--end-time " + std::string(end) + " s ends the run before output.snapshots at " +
                  dropped + " s: " + (n == 1 ? "that snapshot is" : "those snapshots are") +
                  " not written (and not listed in case.resolved.toml)";
  // With no snapshot left, what the case check requires snapshots for goes too (the skin
  // profile is written at the snapshot times, the view frames them): the resolved case must
  // read back.
  if (snaps.empty()) {
    std::string also;
    if (!cfg.output.skin_profile.empty()) also += "output.skin_profile";
    if (cfg.output.has_snapshot_view())
      also += also.empty() ? "output.snapshot_view" : " and output.snapshot_view";
    if (!also.empty())
      w += "; with no snapshot left, " + also + " (written at the snapshot times) " +
           (also.find(" and ") == std::string::npos ? "is" : "are") + " dropped too";
    cfg.output.skin_profile.clear();
    cfg.output.snapshot_view = Box{};
  }
  return {w};
}

}  // namespace slamsph
