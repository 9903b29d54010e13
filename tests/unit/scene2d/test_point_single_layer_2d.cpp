// The dense point single layer (PointSingleLayer2D.hpp) against the spline quadrature of
// the single layer (LayerPotentials2D through InterfaceVelocity2D::singleLayer): for a
// smooth load it converges at first order in the node spacing, with the right sign and
// scale, in free space and above the wall.
#include "Contour2DTesting.hpp"

#include "capsula/testing/ConvergenceOrder.hpp"

#include <capsula/scene2d/InterfaceVelocity2D.hpp>
#include <capsula/scene2d/PointSingleLayer2D.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

using namespace capsula;
using namespace capsula::operators;
using namespace capsula::scene2d;
using capsula::scene2d::testing2d::ellipse;
using capsula::scene2d::testing2d::serialComm;
using capsula::testing::fittedOrder;

// A smooth load with zero net force (a closed membrane's): f = (0.4 kappa + 0.2 x) n, the
// x-dependence making it non-uniform.
Eigen::Vector2d load(const contour::ContourPoint& p)
{
  return (0.4 * p.curvature + 0.2 * p.position.x()) * p.normal;
}

// max |M f - SL[f]| / max |SL[f]| at the nodes of an ellipse (a/b = 0.6) centred 1.6
// above the wall (its lowest point 0.31 above it) or in free space.
double relativeError(int nodes, bool wall)
{
  const contour::Contour c = ellipse(nodes, 0.6, Eigen::Vector2d(0.3, 1.6));
  auto velocity = makeInterfaceVelocity2D(wall, serialComm(), nodes, {}, {});
  const std::vector<double> reference =
      velocity->singleLayer(c, [](const contour::ContourPoint& p, int, double) { return load(p); });
  Eigen::VectorXd f(2 * nodes);
  for (int i = 0; i < nodes; ++i) {
    f.segment<2>(2 * i) = load(c.nodePoint(i));
  }
  const Eigen::VectorXd approximate = pointSingleLayer2D(c, wall) * f;
  double error = 0.0, scale = 0.0;
  for (int k = 0; k < 2 * nodes; ++k) {
    error = std::max(error, std::abs(approximate[k] - reference[static_cast<std::size_t>(k)]));
    scale = std::max(scale, std::abs(reference[static_cast<std::size_t>(k)]));
  }
  return error / scale;
}

} // namespace

// Measured for 32, 64, 128, 256 nodes: 3.1e-2, 1.2e-2, 5.1e-3, 2.3e-3 in free space and
// 2.0e-2, 7.9e-3, 3.6e-3, 1.9e-3 above the wall (fitted orders 1.25 and 1.14: first order
// with the O(h^2 ln h) of the self terms fading). A wrong sign, a missing image or a self
// term off by its logarithm is an O(1) error that does not fall with N.
TEST(PointSingleLayer2D, ConvergesToTheSingleLayerAtFirstOrder)
{
  for (const bool wall : {false, true}) {
    const std::vector<int> nodes{32, 64, 128, 256};
    std::vector<double> errors;
    for (const int n : nodes) {
      errors.push_back(relativeError(n, wall));
    }
    EXPECT_NEAR(fittedOrder(nodes, errors), 1.2, 0.2) << (wall ? "wall" : "free space");
    EXPECT_LT(errors.back(), 3e-3) << (wall ? "wall" : "free space");
  }
}
