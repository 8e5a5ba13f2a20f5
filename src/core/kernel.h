// Smoothing kernels (spec §1): Wendland C2 (default) and the cubic B-spline, both with
// support radius 2h and 2D normalisation. A Kernel is a small value, passed explicitly.
#pragma once
#include <algorithm>
#include <numbers>
#include <string>

namespace slamsph {

enum class KernelType { WendlandC2, CubicSpline };

// The regulariser of the Morris et al. (1997) viscous pair term, r^2 / (r^2 + eta^2) with
// eta^2 = kMorrisEta2 h^2: one value for the water's pass, the contact and their lane loops.
constexpr double kMorrisEta2 = 0.01;

class Kernel {
 public:
  Kernel() = default;
  Kernel(KernelType type, double h);

  KernelType type() const { return type_; }
  double h() const { return h_; }
  double support() const { return 2.0 * h_; }

  // W(r), r >= 0.
  double w(double r) const {
    const double q = r * inv_h_;
    if (q >= 2.0) return 0.0;
    if (type_ == KernelType::WendlandC2) {
      const double t = 1.0 - 0.5 * q;
      const double t2 = t * t;
      return norm_ * t2 * t2 * (2.0 * q + 1.0);
    }
    if (q < 1.0) return norm_ * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
    const double t = 2.0 - q;
    return norm_ * 0.25 * t * t * t;
  }

  // dW/dr, r >= 0. The gradient is dW/dr * r_ij/|r_ij| (spec notation).
  double dw(double r) const {
    const double q = r * inv_h_;
    if (q >= 2.0) return 0.0;
    if (type_ == KernelType::WendlandC2) {
      const double t = 1.0 - 0.5 * q;
      return norm_ * inv_h_ * (-5.0 * q) * t * t * t;
    }
    if (q < 1.0) return norm_ * inv_h_ * (-3.0 * q + 2.25 * q * q);
    const double t = 2.0 - q;
    return norm_ * inv_h_ * (-0.75 * t * t);
  }

  // dW/dr divided by r (finite at r -> 0 for both kernels); saves a division in pair loops.
  double dw_over_r(double r) const {
    return type_ == KernelType::WendlandC2 ? dw_over_r_as<KernelType::WendlandC2>(r)
                                           : dw_over_r_as<KernelType::CubicSpline>(r);
  }

  // The same with the kernel type fixed at compile time (hot loops dispatch once).
  template <KernelType T>
  double dw_over_r_as(double r) const {
    const double q = r * inv_h_;
    if constexpr (T == KernelType::WendlandC2) {
      // Branch-free: zero beyond the support through the clamp.
      const double t = std::max(0.0, 1.0 - 0.5 * q);
      return norm_h2_5_ * t * t * t;
    } else {
      if (q >= 2.0) return 0.0;
      if (q < 1.0) return norm_h2_ * (-3.0 + 2.25 * q);
      const double t = 2.0 - q;
      return q > 0.0 ? norm_h_ * (-0.75 * t * t) / r : 0.0;
    }
  }

  // The two constants of dw_over_r_as<WendlandC2>: 1/h and the factor of t^3, for loops that
  // evaluate it in vector lanes (fluid/gsph_pair_band.h) with the same roundings.
  double inv_h() const { return inv_h_; }
  double wendland_dw_over_r_factor() const { return norm_h2_5_; }

 private:
  KernelType type_ = KernelType::WendlandC2;
  double h_ = 1.0;
  double inv_h_ = 1.0;
  double norm_ = 0.0;
  // norm_ inv_h_, norm_ inv_h_ inv_h_ and norm_ inv_h_ inv_h_ (-5), multiplied in the order
  // the formulas above read, so the values are those of the plain expressions. Stored
  // because a pair loop cannot hoist them itself: they are reached only past its support
  // test, and the compiler does not move floating-point operations out of a conditional path.
  double norm_h_ = 0.0, norm_h2_ = 0.0, norm_h2_5_ = 0.0;
};

KernelType kernel_type_from_name(const std::string& name);  // throws std::invalid_argument
std::string kernel_name(KernelType t);

}  // namespace slamsph
