// New markers graded towards the tether (TetherRegrid2D): the spacing law, and that the
// regridded cell is the same cell (shape, material points, stretch).
#include "capsula/testing/Constants.hpp"
#include <capsula/contour/Contour.hpp>
#include <capsula/contour/ContourLocation.hpp>
#include <capsula/contour/InitialShapes.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/scene2d/ElasticMembrane2D.hpp>
#include <capsula/scene2d/HookeanLaw2D.hpp>
#include <capsula/scene2d/TetherRegrid2D.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using capsula::testing::pi;

using namespace capsula;
using capsula::scene2d::TetherGrading2D;

namespace {

contour::ContourOptions tethered()
{
  contour::ContourOptions options;
  options.closure = contour::Closure::Tethered;
  return options;
}

} // namespace

TEST(TetherRegrid2D, GradedSpacingFollowsTheLaw)
{
  // h(d) = H min(1, f + (1 - f) d / w): with f = 0.1 and w = 1 on a length 2 pi the far
  // spacing is H = 2 I / N, I = w ln(1/f) / (1 - f) + (pi - w) (eq in TetherRegrid2D.hpp).
  const TetherGrading2D grading{0.1, 1.0};
  const double length = 2.0 * pi;
  for (const int n : {64, 65, 256}) {
    const std::vector<double> sigma = scene2d::gradedArcLengths(n, length, grading);
    ASSERT_EQ(sigma.size(), static_cast<std::size_t>(n) + 1);
    EXPECT_EQ(sigma.front(), 0.0);
    EXPECT_EQ(sigma.back(), length);
    const double H = 2.0 * (std::log(10.0) / 0.9 + pi - 1.0) / n;
    double largestRatio = 1.0;
    for (int j = 0; j < n; ++j) {
      const double h = sigma[j + 1] - sigma[j];
      ASSERT_GT(h, 0.0);
      EXPECT_NEAR(sigma[n - j], length - sigma[j], 1e-13); // symmetric about the opposite point
      EXPECT_LT(h, H * (1.0 + 1e-12));
      if (j > 0) {
        largestRatio = std::max(largestRatio, h / (sigma[j] - sigma[j - 1]));
      }
    }
    // The first spacing is the mean of h over it: f H (1 + O(g h)), within 10% at N >= 64.
    EXPECT_NEAR((sigma[1] - sigma[0]) / (0.1 * H), 1.0, 0.1) << n;
    // The far field is even: the spacing at the opposite point is H.
    EXPECT_NEAR(sigma[n / 2 + 1] - sigma[n / 2], H, 1e-12 * H) << n;
    // Neighbouring spacings grow by at most e^{(1 - f) H / w} (the geometric ratio of the
    // graded part): under 4% at 64 markers.
    EXPECT_LT(largestRatio, std::exp(0.9 * H) + 1e-12) << n;
  }
  // f = 1 is even spacing.
  const std::vector<double> even = scene2d::gradedArcLengths(10, 5.0, {1.0, 1.0});
  for (int j = 0; j <= 10; ++j) {
    EXPECT_NEAR(even[j], 0.5 * j, 1e-14);
  }
  EXPECT_THROW(scene2d::gradedArcLengths(64, length, {0.0, 1.0}), core::InputError);
  EXPECT_THROW(scene2d::gradedArcLengths(64, length, {1.5, 1.0}), core::InputError);
  EXPECT_THROW(scene2d::gradedArcLengths(64, length, {0.1, -1.0}), core::InputError);
}

TEST(TetherRegrid2D, RigidlyTurnedEllipseKeepsItsMaterialPoints)
{
  // The reference ellipse (a/b = 2) turned by 0.7 rad about its centre and lifted: no
  // stretch anywhere. The new tether is the lowest point of the turned ellipse, and its
  // reference position must be that point turned back; every new marker's reference and
  // current positions differ by the same rigid motion; the tethered membrane through the
  // new markers has stretch 1 and (almost) no tension. Tolerances: the splines' O(h^4)
  // interpolation error at 96 markers (~1e-7 in position, ~1e-5 in the stretch).
  contour::EllipseShape shape;
  shape.aspectRatio = 2.0;
  const Eigen::Matrix2Xd referenceNodes = contour::ellipseNodes(96, shape);
  const double turn = 0.7;
  Eigen::Matrix2d rotation;
  rotation << std::cos(turn), -std::sin(turn), std::sin(turn), std::cos(turn);
  const Eigen::Vector2d lift(0.3, 2.0);
  const Eigen::Matrix2Xd currentNodes = (rotation * referenceNodes).colwise() + lift;
  const contour::Contour reference(referenceNodes);
  const contour::Contour current(currentNodes);
  const Eigen::Vector2d anchor(0.0, 0.005);
  const scene2d::TetherRegrid2D regrid = scene2d::regridAtTether(reference, current, {0.1, 1.0}, anchor);

  const contour::ContourLocation lowest = contour::lowestPoint(current);
  const Eigen::Vector2d lowestPoint = current.positionAt(lowest.segment, lowest.t);
  EXPECT_LT((regrid.currentNodes.col(0) - anchor).norm(), 1e-15);
  const Eigen::Vector2d shift = anchor - lowestPoint;
  for (int j = 0; j < 96; ++j) {
    // current = R reference + lift + shift, marker by marker.
    const Eigen::Vector2d expected = rotation * regrid.referenceNodes.col(j) + lift + shift;
    EXPECT_NEAR((regrid.currentNodes.col(j) - expected).norm(), 0.0, 1e-6) << j;
  }
  // Node 0 is the lowest point: every other marker is above the anchor.
  for (int j = 1; j < 96; ++j) {
    EXPECT_GT(regrid.currentNodes(1, j), anchor.y()) << j;
  }
  // Spacing graded: the first reference segment is about f H, much shorter than a far one.
  const double first = (regrid.referenceNodes.col(1) - regrid.referenceNodes.col(0)).norm();
  const double far = (regrid.referenceNodes.col(49) - regrid.referenceNodes.col(48)).norm();
  EXPECT_LT(first, 0.15 * far);
  const scene2d::ElasticMembrane2D membrane(contour::Contour(regrid.referenceNodes, tethered()),
                                            scene2d::HookeanLaw2D(1.0));
  const scene2d::MembraneState2D state = membrane.evaluate(contour::Contour(regrid.currentNodes, tethered()));
  EXPECT_LT((state.stretch().array() - 1.0).abs().maxCoeff(), 1e-5);
}

TEST(TetherRegrid2D, StretchedCircleKeepsItsStretch)
{
  // The unit circle scaled by 1.4 and its markers slid along it (theta = theta0 + 0.3 sin
  // theta0): stretch 1.4 (1 + 0.3 cos theta0) at material angle theta0. The regridded markers
  // must carry the same stretch at the same material points: at new marker j, with
  // reference angle theta0_j, omega = 1.4 (1 + 0.3 cos theta0_j) (to ~1e-4 at 128 markers,
  // the stretch spline's O(h^3) slope error).
  const int n = 128;
  Eigen::Matrix2Xd moved(2, n);
  for (int i = 0; i < n; ++i) {
    const double theta0 = 2.0 * pi * i / n;
    const double theta = theta0 + 0.3 * std::sin(theta0);
    moved.col(i) = 1.4 * Eigen::Vector2d(std::cos(theta), std::sin(theta)) + Eigen::Vector2d(0.0, 3.0);
  }
  const contour::Contour reference(contour::circleNodes(n, 1.0));
  const contour::Contour current(moved);
  const scene2d::TetherRegrid2D regrid = scene2d::regridAtTether(reference, current, {0.2, 0.8}, {0.0, 0.005});
  // The lowest point of the current circle is at angle -pi/2, material angle theta0 with
  // theta0 + 0.3 sin theta0 = -pi/2 (mod 2 pi).
  double theta0 = -pi / 2;
  for (int i = 0; i < 50; ++i) {
    theta0 -= (theta0 + 0.3 * std::sin(theta0) + pi / 2) / (1.0 + 0.3 * std::cos(theta0));
  }
  EXPECT_NEAR(std::remainder(regrid.tetherReferenceArcLength - theta0, 2.0 * pi), 0.0, 1e-5);
  const scene2d::ElasticMembrane2D membrane(contour::Contour(regrid.referenceNodes, tethered()),
                                            scene2d::HookeanLaw2D(1.0));
  const scene2d::MembraneState2D state = membrane.evaluate(contour::Contour(regrid.currentNodes, tethered()));
  double worst = 0.0;
  for (int j = 1; j < n; ++j) {
    const double angle = std::atan2(regrid.referenceNodes(1, j), regrid.referenceNodes(0, j));
    worst = std::max(worst, std::abs(state.stretch()(j) - 1.4 * (1.0 + 0.3 * std::cos(angle))));
  }
  EXPECT_LT(worst, 1e-3);
}
