#pragma once
// The undisturbed flow u_inf of eqs 3.15 and 3.59: a linear Stokes flow
// u_inf(x) = velocity + gradient . x, with gradient(i, j) = d u_i / d x_j, and the flow of a
// scene, BackgroundFlow: a linear flow plus the quadratic profile of plane Poiseuille flow.
// Dimensionless with velocity scale k L (thesis eq 3.15): simple shear along x over the
// wall y = 0 is u_inf = (y, 0, 0), shear rate 1.
#include <capsula/mesh/Vec3.hpp>

namespace capsula::operators {

/// u_inf(x) = velocity + gradient x in Dim dimensions (3 for the surfaces, 2 for the contours).
template <int Dim>
struct LinearFlowOf {
  using Vector = Eigen::Matrix<double, Dim, 1>;
  using Matrix = Eigen::Matrix<double, Dim, Dim>;

  Vector velocity = Vector::Zero();
  Matrix gradient = Matrix::Zero();

  Vector at(const Vector& x) const { return velocity + gradient * x; }

  /// u_inf = (rate * y, 0, ...).
  static LinearFlowOf simpleShear(double rate = 1.0)
  {
    LinearFlowOf flow;
    flow.gradient(0, 1) = rate;
    return flow;
  }
  /// Fluid at rest.
  static LinearFlowOf quiescent() { return LinearFlowOf{}; }
};

using LinearFlow = LinearFlowOf<3>;

/// u_inf(x) = linear.at(x) + curvature y^2 e_x: a linear flow, plus for plane Poiseuille flow
/// in the channel 0 < y < H (domain/FlowProfile.hpp, u = k y (1 - y / H)) the term of
/// curvature -k / H. A Stokes flow with the uniform pressure gradient dp/dx = 2 curvature
/// (mu = 1): its Laplacian is 2 curvature e_x.
struct BackgroundFlow {
  LinearFlow linear;
  double curvature = 0.0;

  BackgroundFlow() = default;
  /// The linear flow itself (curvature 0).
  BackgroundFlow(const LinearFlow& flow) : linear(flow) {} // NOLINT(google-explicit-constructor)

  mesh::Vec3 at(const mesh::Vec3& x) const
  {
    mesh::Vec3 u = linear.at(x);
    u[0] += curvature * x[1] * x[1];
    return u;
  }
  /// d u_i / d x_j at x.
  mesh::Mat3 gradientAt(const mesh::Vec3& x) const
  {
    mesh::Mat3 gradient = linear.gradient;
    gradient(0, 1) += 2.0 * curvature * x[1];
    return gradient;
  }
};

/// What the velocity of the cells depends on besides their shape and load.
struct FlowConditions {
  double capillaryNumber = 1.0; ///< Ca = mu k L / E (eq 3.16)
  BackgroundFlow background = LinearFlow::simpleShear();
};

} // namespace capsula::operators
