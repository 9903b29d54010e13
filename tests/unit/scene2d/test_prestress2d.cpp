// 2D membrane prestress (elasticity/Prestress.hpp, the contour overload): the reference is the initial contour
// shrunk by 1 + alpha about its area centroid, so the initial contour carries the uniform
// tension E alpha and, for a circle, the Laplace load (E alpha / R) n.
#include <capsula/contour/Contour.hpp>
#include <capsula/contour/ContourMetrics.hpp>
#include <capsula/contour/InitialShapes.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/scene2d/ElasticMembrane2D.hpp>
#include <capsula/elasticity/Prestress.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using capsula::contour::Contour;
using capsula::elasticity::prestressedReference;
using capsula::scene2d::ElasticMembrane2D;
using capsula::scene2d::HookeanLaw2D;
using capsula::scene2d::MembraneState2D;

Eigen::Matrix2Xd offCentreEllipse(int n)
{
  capsula::contour::EllipseShape shape;
  shape.aspectRatio = 0.5;
  shape.orientation = 0.3;
  shape.centre = Eigen::Vector2d(0.4, 1.2);
  shape.firstNodeAngle = -0.5 * std::acos(-1.0);
  return capsula::contour::ellipseNodes(n, shape);
}

TEST(Prestress2D, ShrinksAboutTheCentroidByOnePlusAlpha)
{
  const Eigen::Matrix2Xd initial = offCentreEllipse(64);
  const double alpha = 0.2;
  const Eigen::Matrix2Xd reference = prestressedReference(initial, alpha);
  const Contour a(initial), r(reference);
  // A similarity about the centroid: the centroid stays (to round-off of O(1) numbers), lengths
  // scale by 1/(1 + alpha) and areas by its square. A factor 1 + alpha instead of its inverse,
  // or a shrink about the origin, fails these by 0.1 or more.
  EXPECT_LT((capsula::contour::centroid(r) - capsula::contour::centroid(a)).norm(), 1e-13);
  EXPECT_NEAR(r.length() * (1.0 + alpha), a.length(), 1e-12);
  EXPECT_NEAR(capsula::contour::enclosedArea(r) * (1.0 + alpha) * (1.0 + alpha), capsula::contour::enclosedArea(a),
              1e-12);
  EXPECT_EQ((prestressedReference(initial, 0.0) - initial).cwiseAbs().maxCoeff(), 0.0);
}

TEST(Prestress2D, InitialContourCarriesTheUniformTensionAndTheLaplaceLoad)
{
  const double youngModulus = 2.5, alpha = 0.15, radius = 1.3;
  const Eigen::Vector2d centre(0.5, 2.0);
  const Contour initial(capsula::contour::circleNodes(128, radius, centre));
  const ElasticMembrane2D membrane(Contour(prestressedReference(initial.nodes(), alpha)), HookeanLaw2D(youngModulus));
  const MembraneState2D state = membrane.evaluate(initial);
  const double gamma = youngModulus * alpha; // E (omega - 1), omega = 1 + alpha
  // Both arc lengths come from splines of similar polygons, so omega = 1 + alpha to round-off.
  EXPECT_LT((state.stretch().array() - (1.0 + alpha)).abs().maxCoeff(), 1e-12);
  EXPECT_LT((state.tension().array() - gamma).abs().maxCoeff(), 1e-12);
  // Laplace: Delta f = (gamma / R) n; the spline curvature of a 128-point circle is exact to
  // (2 pi / 128)^2 / 12 = 2.0e-4 (test_tension2d_load), hence 3e-4 relative.
  double worst = 0.0;
  for (int i = 0; i < initial.numberOfNodes(); ++i) {
    const Eigen::Vector2d n = (initial.nodes().col(i) - centre) / radius;
    worst = std::max(worst, (state.load().col(i) - gamma / radius * n).norm());
  }
  EXPECT_LT(worst / (gamma / radius), 3e-4);
}

TEST(Prestress2D, RejectsANegativeOrNonFinitePrestress)
{
  const Eigen::Matrix2Xd initial = offCentreEllipse(16);
  EXPECT_THROW(prestressedReference(initial, -0.01), capsula::core::InputError);
  EXPECT_THROW(prestressedReference(initial, std::numeric_limits<double>::quiet_NaN()), capsula::core::InputError);
}

} // namespace
