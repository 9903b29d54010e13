#pragma once
// The linear spring of a bond or a tether: a spring of stiffness sigma and rest length
// lambda between a point x of the membrane and its anchor A pulls the membrane with
//
//   F = -sigma (L - lambda) (x - A) / L,    L = |x - A|,
//
// towards the anchor when stretched (L > lambda), away from it when compressed. It is
// -dE/dx of the spring energy E = sigma (L - lambda)^2 / 2, and its stiffness -dF/dx is the
// Hessian of E. Shared by the receptor-ligand bonds (BondPopulation.hpp) and the tether
// (Tether.hpp).
#include <capsula/mesh/Vec3.hpp>

namespace capsula::adhesion {

/// The spring's force on the membrane point `x` (see above). A spring of zero length has no
/// direction; it can only be compressed (lambda >= 0), so it pushes off the wall (+y).
inline mesh::Vec3 springForce(const mesh::Vec3& x, const mesh::Vec3& anchor, double stiffness, double restLength)
{
  const mesh::Vec3 d = x - anchor;
  const double length = d.norm();
  const mesh::Vec3 direction = length > 0.0 ? mesh::Vec3(d / length) : mesh::Vec3::UnitY();
  return -stiffness * (length - restLength) * direction;
}

/// The spring's stiffness -dF/dx at `x`: d/dx of (L - lambda) e is (1 - lambda/L)(I - e e^T)
/// + e e^T. A spring of zero length pushes along e_y (springForce): only its stretch along e_y
/// is kept.
inline mesh::Mat3 springStiffness(const mesh::Vec3& x, const mesh::Vec3& anchor, double stiffness, double restLength)
{
  const mesh::Vec3 d = x - anchor;
  const double length = d.norm();
  if (length == 0.0) {
    return stiffness * mesh::Vec3::UnitY() * mesh::Vec3::UnitY().transpose();
  }
  const mesh::Vec3 e = d / length;
  const double ratio = restLength / length;
  return stiffness * ((1.0 - ratio) * mesh::Mat3::Identity() + ratio * e * e.transpose());
}

} // namespace capsula::adhesion
