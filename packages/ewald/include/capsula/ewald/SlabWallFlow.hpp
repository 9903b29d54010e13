#pragma once
// The Stokes flow in the slab 0 < y < H with no slip on y = 0 and a velocity V e^{i k.x}
// prescribed on y = H, k = (k_x, k_z), a = |k| > 0 (the far-wall correction of
// SpectralEwaldChannel2P.hpp). With t = (-k_z, k_x) / a, V_l = V.k / a, V_t = V.t:
//   u_t(y) = V_t sinh(a y) / sinh(a H),
// and in the plane of k and e_y, w = u_y = c1 f1(y) + c2 f2(y), u_l = i w' / a (continuity),
//   f1 = sinh(a y) - a y cosh(a y),   f2 = y sinh(a y)
// (the solutions of (d^2 - a^2)^2 w = 0 with w(0) = w'(0) = 0), and w(H) = V_y,
// w'(H) = -i a V_l:
//   c1 = (V_y f2'(H) + i a V_l f2(H)) / Delta,   c2 = (a^2 H sinh(a H) V_y - i a V_l f1(H)) / Delta,
//   Delta = f1 f2' - f2 f1' = sinh^2(a H) - a^2 H^2,   f1' = -a^2 y sinh(a y),
//   f2' = sinh(a y) + a y cosh(a y).
// The mode k = 0 is u = V y / H for the parallel components (V_y = 0 there: no net flux).
#include <complex>

namespace capsula::ewald {

/// The slab's solution for one mode: its velocity at any height.
class SlabWallFlow {
public:
  /// k = (kx, kz) != 0, far-wall velocity V (x, y, z components), slab height H.
  SlabWallFlow(double kx, double kz, double height, const std::complex<double> farWallVelocity[3]);

  /// u(y) (x, y, z components), 0 <= y <= H.
  void velocity(double y, std::complex<double> u[3]) const;

  double kx() const { return kx_; }
  double kz() const { return kz_; }

private:
  double kx_, kz_, a_;
  std::complex<double> transverse_; // V_t / sinh(a H)
  std::complex<double> c1_, c2_;
};

} // namespace capsula::ewald
