#include <capsula/mesh/Shapes.hpp>

#include <capsula/core/Error.hpp>
#include <capsula/mesh/Icosphere.hpp>

#include <algorithm>
#include <vector>

namespace capsula::mesh {

using core::InputError;
using core::require;

namespace {

/// The unit icosphere with every node moved by `map`, then placed.
template <typename Map>
SurfaceMesh mapUnitSphere(int level, Map&& map, const Placement& placement)
{
  SurfaceMesh mesh = makeIcosphere(level);
  std::vector<double> x = mesh.positions();
  for (int node = 0; node < mesh.numNodes(); ++node) {
    Eigen::Map<Vec3> p(x.data() + 3 * node);
    const Vec3 onSphere = p;
    p = map(onSphere);
  }
  mesh.setPositions(x);
  applyPlacement(mesh, placement);
  return mesh;
}

} // namespace

SurfaceMesh makeSphere(int level, double radius, const Placement& placement)
{
  require<InputError>(radius > 0.0, "makeSphere: radius = ", radius, " must be positive");
  return mapUnitSphere(
      level, [radius](const Vec3& p) -> Vec3 { return radius * p; }, placement);
}

SurfaceMesh makeEllipsoid(int level, const Vec3& semiAxes, const Placement& placement)
{
  require<InputError>(semiAxes.minCoeff() > 0.0, "makeEllipsoid: semi-axes (", semiAxes[0], ", ", semiAxes[1], ", ",
                      semiAxes[2], ") must all be positive");
  return mapUnitSphere(
      level, [&semiAxes](const Vec3& p) -> Vec3 { return semiAxes.cwiseProduct(p); }, placement);
}

SurfaceMesh makeSpheroid(int level, double equatorialRadius, double polarRadius, const Placement& placement)
{
  return makeEllipsoid(level, Vec3(equatorialRadius, equatorialRadius, polarRadius), placement);
}

SurfaceMesh makeBiconcaveCell(int level, const BiconcaveProfile& profile, const Placement& placement)
{
  const double r0 = profile.radius;
  require<InputError>(r0 > 0.0, "makeBiconcaveCell: radius = ", r0, " must be positive");
  const auto thickness = [&profile](double s) { return profile.c0 + s * (profile.c1 + s * profile.c2); };
  // The half-thickness must stay positive for 0 <= s <= 1 or the surface self-intersects;
  // the polynomial in s is quadratic, so checking the ends and the vertex suffices.
  double lowest = std::min(thickness(0.0), thickness(1.0));
  if (profile.c2 != 0.0) {
    const double sVertex = -profile.c1 / (2.0 * profile.c2);
    if (sVertex > 0.0 && sVertex < 1.0) {
      lowest = std::min(lowest, thickness(sVertex));
    }
  }
  require<InputError>(lowest > 0.0, "makeBiconcaveCell: coefficients c0 = ", profile.c0, ", c1 = ", profile.c1,
                      ", c2 = ", profile.c2, " give a non-positive thickness somewhere on the disc");
  return mapUnitSphere(
      level,
      [r0, &thickness](const Vec3& p) -> Vec3 {
        const double s = p[0] * p[0] + p[1] * p[1];
        return Vec3(r0 * p[0], r0 * p[1], 0.5 * r0 * p[2] * thickness(s));
      },
      placement);
}

} // namespace capsula::mesh
