#include "capsula/elasticity/Prestress2D.hpp"

#include <capsula/contour/Contour.hpp>
#include <capsula/contour/ContourMetrics.hpp>
#include <capsula/core/Error.hpp>

#include <cmath>

namespace capsula::elasticity {

Eigen::Matrix2Xd prestressedReference2D(const Eigen::Matrix2Xd& initial, double prestress)
{
  core::require<core::InputError>(std::isfinite(prestress) && prestress >= 0.0,
                                  "the 2D membrane prestress alpha (initial stretch 1 + alpha) is ", prestress,
                                  "; give alpha >= 0 (e.g. 0.2 for 20%, 0 for none)");
  const Eigen::Vector2d c = contour::centroid(contour::Contour(initial));
  // X = x - alpha/(1 + alpha) (x - c): the same map as c + (x - c)/(1 + alpha), exact at alpha = 0.
  const double pull = prestress / (1.0 + prestress);
  Eigen::Matrix2Xd reference = initial;
  reference -= pull * (initial.colwise() - c);
  return reference;
}

} // namespace capsula::elasticity
