#include "capsula/scene/ShearDeformation.hpp"

#include <cmath>

namespace capsula::scene {

ShearDeformation shearDeformation(const mesh::EquivalentEllipsoid& ellipsoid)
{
  const mesh::Mat3& axes = ellipsoid.axes;
  int vorticityAxis = 0;
  for (int i = 1; i < 3; ++i) {
    if (std::abs(axes(2, i)) > std::abs(axes(2, vorticityAxis))) {
      vorticityAxis = i;
    }
  }
  int a = (vorticityAxis + 1) % 3;
  int b = (vorticityAxis + 2) % 3;
  if (ellipsoid.semiAxes[b] > ellipsoid.semiAxes[a]) {
    std::swap(a, b);
  }
  ShearDeformation d;
  const double l1 = ellipsoid.semiAxes[a], l2 = ellipsoid.semiAxes[b];
  const double l3 = ellipsoid.semiAxes[vorticityAxis];
  d.semiAxes = mesh::Vec3(l1, l2, l3);
  d.D12 = (l1 - l2) / (l1 + l2);
  d.D13 = std::abs(l1 - l3) / (l1 + l3);
  d.D23 = std::abs(l2 - l3) / (l2 + l3);
  // The axis is a direction without sign: fold the angle into (-90, 90].
  double angle = std::atan2(axes(1, a), axes(0, a)) * 180.0 / M_PI;
  if (angle > 90.0) {
    angle -= 180.0;
  } else if (angle <= -90.0) {
    angle += 180.0;
  }
  d.inclinationDegrees = angle;
  return d;
}

} // namespace capsula::scene
