#pragma once
// Initial cell shapes: the unit icosphere of a given level mapped node by node
// onto the target surface, then placed (centre and orientation). Every node,
// vertex or midside, lies exactly on the target surface; the outward orientation
// of the icosphere is kept because each map preserves orientation.
#include <capsula/mesh/Placement.hpp>
#include <capsula/mesh/SurfaceMesh.hpp>

namespace capsula::mesh {

/// Sphere of the given radius.
SurfaceMesh makeSphere(int level, double radius, const Placement& placement = {});

/// Ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1 in body axes, semiAxes = (a, b, c),
/// by the affine map (x, y, z) -> (a x, b y, c z) of the unit sphere.
SurfaceMesh makeEllipsoid(int level, const Vec3& semiAxes, const Placement& placement = {});

/// Spheroid with its symmetry axis along body z: semi-axes (equatorial,
/// equatorial, polar). Oblate if polar < equatorial: the resting platelet is
/// makeSpheroid(level, 1.5, 0.25) in micrometres (aspect ratio 6:1, Haga et al. 1998).
SurfaceMesh makeSpheroid(int level, double equatorialRadius, double polarRadius, const Placement& placement = {});

/// Evans & Fung (1972) biconcave red-cell profile, symmetry axis along body z:
///   z(r) = +-(R0 / 2) sqrt(1 - (r/R0)^2) (c0 + c1 (r/R0)^2 + c2 (r/R0)^4),
/// r the distance from the axis. With R0 = 3.91 um (the disc radius) this is the
/// standard resting red cell (diameter 7.82 um, thickness 0.81 um at the centre and
/// 2.57 um at the thickest, r = 2.74 um): area ~134 um^2, volume ~94 um^3, reduced
/// volume ~0.64 (values pinned by the unit tests).
/// Lengths are in whatever unit `radius` is given in: radius = 1 is the cell in
/// units of R0, radius = 3.91 in micrometres.
struct BiconcaveProfile {
  double radius = 1.0; ///< R0, the disc radius
  double c0 = 0.207161;
  double c1 = 2.002558;
  double c2 = -1.122762;
};

/// The unit-sphere point (x, y, z) goes to (R0 x, R0 y, z (R0/2)(c0 + c1 s + c2 s^2))
/// with s = x^2 + y^2: since |z| = sqrt(1 - s) on the sphere, this lands on the profile.
SurfaceMesh makeBiconcaveCell(int level, const BiconcaveProfile& profile = {}, const Placement& placement = {});

} // namespace capsula::mesh
