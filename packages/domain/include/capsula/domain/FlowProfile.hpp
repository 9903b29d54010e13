#pragma once
// The undisturbed flow of a domain, u_inf = k(t) f(y) e_x, dimensionless with the velocity
// scale k a (thesis eq 3.15), k being the shear rate at the lower wall (or of the unbounded
// shear), so that the capillary number Ca = mu k a / G keeps its meaning in every domain:
//
//   Shear:      f(y) = y. Above one wall or unbounded: simple shear. In a channel of
//               height H: plane Couette flow, the upper wall sliding at k H.
//   Poiseuille: f(y) = y (1 - y / H), pressure-driven flow in a channel of height H
//               (needs the channel): the wall shear rates are k and -k, the centre-line
//               velocity k H / 4, the flux per unit width k H^2 / 6, driven by the
//               pressure gradient dp/dx = -2 mu k / H.
//
// k(t) (a pulsatile or tabulated waveform, operators/ShearRate.hpp) multiplies either.
#include "capsula/domain/Domain.hpp"

#include <array>
#include <string>
#include <vector>

namespace capsula::domain {

enum class FlowProfileKind { Shear, Poiseuille };

/// The deck names of the profiles ('Flow/Profile'), in the order of FlowProfileKind.
const std::vector<std::string>& flowProfileNames();
std::string flowProfileName(FlowProfileKind kind);

class FlowProfile {
public:
  /// Throws core::InputError, naming 'Flow/Profile' and 'Wall/Channel height', for a
  /// Poiseuille profile in a domain without a channel.
  FlowProfile(FlowProfileKind kind, const Domain& domain);

  FlowProfileKind kind() const { return kind_; }
  bool isLinear() const { return kind_ == FlowProfileKind::Shear; }

  /// f(y) and f'(y): the streamwise velocity and the shear rate at height y, for k = 1.
  double velocity(double y) const;
  double shearRate(double y) const;
  /// c in f(y) = y + c y^2, the form of every profile: -1 / H for Poiseuille, 0 for shear.
  double curvature() const;
  /// u_inf(x) for k = 1.
  std::array<double, 3> velocityAt(const double x[3]) const;
  /// d u_i / d x_j at x for k = 1 (row-major 3 x 3; only (0, 1) is non-zero).
  std::array<double, 9> gradientAt(const double x[3]) const;

  /// The velocity f(wall.height) e_x with which a wall slides (0 for the lower wall).
  double wallVelocity(const Wall& wall) const { return velocity(wall.height); }
  /// The shear rate of the undisturbed flow on a wall, seen from the fluid: d u_x / d n
  /// with n the wall's normal into the fluid (1 on the lower wall; 1 for Poiseuille's
  /// upper wall too, since the flow is symmetric).
  double wallShearRate(const Wall& wall) const { return wall.fluidSide * shearRate(wall.height); }
  /// The volume flux per unit width, int_0^H f dy, in a channel (k = 1).
  double fluxPerWidth() const;

  std::string describe() const;

private:
  FlowProfileKind kind_;
  double height_; ///< the channel height H (0 without a channel)
};

} // namespace capsula::domain
