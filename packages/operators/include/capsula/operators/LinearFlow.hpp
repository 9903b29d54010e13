#pragma once
// The undisturbed flow u_inf of eqs 3.15 and 3.59: a linear Stokes flow
// u_inf(x) = velocity + gradient . x, with gradient(i, j) = d u_i / d x_j.
// Dimensionless with velocity scale k L (thesis eq 3.15): simple shear along x over the
// wall y = 0 is u_inf = (y, 0, 0), shear rate 1.
#include <capsula/mesh/Vec3.hpp>

namespace capsula::operators {

struct LinearFlow {
  mesh::Vec3 velocity = mesh::Vec3::Zero();
  mesh::Mat3 gradient = mesh::Mat3::Zero();

  mesh::Vec3 at(const mesh::Vec3& x) const { return velocity + gradient * x; }

  /// u_inf = (rate * y, 0, 0).
  static LinearFlow simpleShear(double rate = 1.0)
  {
    LinearFlow flow;
    flow.gradient(0, 1) = rate;
    return flow;
  }
  /// Fluid at rest.
  static LinearFlow quiescent() { return LinearFlow{}; }
};

/// What the velocity of the cells depends on besides their shape and load.
struct FlowConditions {
  double capillaryNumber = 1.0; ///< Ca = mu k L / E (eq 3.16)
  LinearFlow background = LinearFlow::simpleShear();
};

} // namespace capsula::operators
