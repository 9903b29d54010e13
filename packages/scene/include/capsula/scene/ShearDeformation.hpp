#pragma once
// Taylor deformation parameters of a cell in shear along x with the velocity gradient
// along y (u_inf = (k y, 0, 0)), thesis eq 3.51.
//
// mesh::equivalentEllipsoid sorts the semi-axes by length, but the thesis's D12 of a
// cell in shear is the deformation IN THE SHEAR PLANE (xy): D12 = (L - B)/(L + B) with L
// and B the longest and shortest axis seen in the profile of Figs 5.5-5.6 (Lac et al.
// 2004 use the same definition). For a capsule the semi-axis along the vorticity (z) is
// usually the middle one, so sorting by length would mix planes. Here:
//   axis 3 = the ellipsoid axis most aligned with z (the vorticity axis),
//   axes 1, 2 = the other two (they lie in, or close to, the xy plane), l1 >= l2,
//   D12 = (l1 - l2)/(l1 + l2), D13 = |l1 - l3|/(l1 + l3), D23 = |l2 - l3|/(l2 + l3),
// and the inclination is the angle of axis 1 from the flow direction x, in the xy plane,
// in degrees in (-90, 90] (positive: tilted towards +y, as a capsule in shear).
#include <capsula/mesh/EquivalentEllipsoid.hpp>

namespace capsula::scene {

struct ShearDeformation {
  double D12 = 0.0, D13 = 0.0, D23 = 0.0;
  double inclinationDegrees = 0.0;
  mesh::Vec3 semiAxes = mesh::Vec3::Zero(); ///< (l1, l2, l3) as defined above
};

ShearDeformation shearDeformation(const mesh::EquivalentEllipsoid& ellipsoid);

} // namespace capsula::scene
