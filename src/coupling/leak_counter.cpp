#include "coupling/leak_counter.h"

#include <cmath>
#include <limits>

namespace slamsph {

long update_leak_flags(FluidParticles& f, const ContactParticles& c, const NeighbourList& fc,
                       const Executor& exec) {
  // Split by pairs: only the fluid next to a surface has any (Executor::for_each_weighted; a
  // pair, a distance, costs about 3 items without pairs).
  exec.for_each_weighted(
      f.size(), fc.start.data(),
      [&](std::size_t i) {
        if (f.crossed[i]) return;
        double best = std::numeric_limits<double>::max();
        std::uint32_t nearest = 0;
        bool any = false;
        for (std::uint32_t k = fc.start[i]; k < fc.start[i + 1]; ++k) {
          const std::uint32_t s = fc.index[k];
          // Ghosts lie behind surfaces by construction; failed particles are debris, not a wall.
          if (c.ghost[s] || c.debris[s]) continue;
          const double d2 = norm2(f.x[i] - c.x[s]);
          if (d2 < best) {
            best = d2;
            nearest = s;
            any = true;
          }
        }
        if (!any) return;
        const Vec2 n = c.normal[nearest];
        const double spacing = std::sqrt(c.volume[nearest]);
        // Only particles within one spacing are judged; farther ones cannot be inside.
        if (best > spacing * spacing) return;
        if (norm2(n) == 0.0 || dot(f.x[i] - c.x[nearest], n) < -0.25 * spacing) f.crossed[i] = 1;
      },
      3);
  long count = 0;
  for (std::uint8_t b : f.crossed) count += b;
  return count;
}

}  // namespace slamsph
