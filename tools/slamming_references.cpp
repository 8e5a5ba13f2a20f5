// Prints the slamming-coefficient reference curves of src/io/reference_curves as CSV, for
// the post-processing of scripts/validate_slamming.sh (so the formulas live in one place).
// Columns: s/D, then Cs of every theory; a comment line per theory says 2D or 3D.
#include <cmath>
#include <cstdio>

#include "io/reference_curves.h"

int main() {
  using namespace slamsph;
  const auto theories = all_slamming_theories();
  for (SlammingTheory th : theories)
    std::printf("# %s: %s\n", slamming_theory_name(th),
                slamming_theory_is_2d(th) ? "2D potential-flow theory"
                                          : "3D experimental fit (finite cylinders, air)");
  std::printf("s/D");
  for (SlammingTheory th : theories) std::printf(",%s", slamming_theory_name(th));
  std::printf("\n");
  for (int i = 0; i <= 800; ++i) {
    const double sd = 0.0005 * i;
    std::printf("%.4f", sd);
    for (SlammingTheory th : theories) {
      const double cs = slamming_coefficient(th, sd);
      if (std::isnan(cs))
        std::printf(",");
      else
        std::printf(",%.8f", cs);
    }
    std::printf("\n");
  }
  return 0;
}
