// The pieces of the tether procedure (thesis Section 4.1) and the initial cell (Fig. 4.1).
#include <capsula/contour/Contour.hpp>
#include <capsula/contour/ContourMetrics.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/scene2d/CellContour2D.hpp>
#include <capsula/scene2d/TetherProcedure2D.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace capsula;
using namespace capsula::scene2d;

TEST(CellContour2D, EllipsesHaveAreaPiAndTheirLowestNodeAtTheGap)
{
  for (const double ab : {0.25, 0.5, 1.0}) {
    CellSettings2D cell;
    cell.aspectRatio = ab;
    cell.numberOfPoints = 128;
    const contour::Contour c(initialCellNodes(cell));
    // L = sqrt(ab) = 1: area pi for every a/b; the spline's area error at 128 points is
    // below 1e-6 even for a/b = 0.25 (capsula::contour tests).
    EXPECT_NEAR(contour::enclosedArea(c), M_PI, 1e-6 * M_PI) << "a/b = " << ab;
    // Node 0 is the bottom of a symmetric contour, so the spline's minimum is that node.
    EXPECT_NEAR(c.nodes()(1, 0), 0.005, 1e-15);
    EXPECT_NEAR(contour::extent(c, 1).min, 0.005, 1e-12);
    // a lies along x: x_max - x_min = 2a = 2 sqrt(a/b).
    EXPECT_NEAR(contour::cellLength(c), 2.0 * flowSemiAxis(cell), 1e-9);
  }
}

TEST(TetherProcedure2D, TheLowestNodeMovesToTheAnchorAndBecomesNodeZero)
{
  CellSettings2D cell;
  cell.numberOfPoints = 40;
  cell.aspectRatio = 0.5;
  // Turn the ellipse so that its lowest node is not node 0, and lift it.
  Eigen::Matrix2Xd nodes = initialCellNodes(cell);
  const double angle = 0.7;
  Eigen::Matrix2d rotation;
  rotation << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  nodes = (rotation * nodes).colwise() + Eigen::Vector2d(3.0, 2.0);
  int lowest = 0;
  for (int i = 1; i < nodes.cols(); ++i) {
    if (nodes(1, i) < nodes(1, lowest))
      lowest = i;
  }
  ASSERT_NE(lowest, 0);

  const Eigen::Vector2d anchor(0.0, 0.005);
  const TetherPlacement2D placement = tetherPlacement(nodes, anchor);
  EXPECT_EQ(placement.lowestNode, lowest);
  const Eigen::Matrix2Xd tethered = tetheredNodes(nodes, placement);
  EXPECT_LT((tethered.col(0) - anchor).norm(), 1e-15); // x + (anchor - x): round-off
  for (int i = 0; i < nodes.cols(); ++i) {
    // A rigid shift and a cyclic relabelling: node i is old node (i + lowest) mod N.
    const Eigen::Vector2d expected = nodes.col((i + lowest) % nodes.cols()) + placement.shift;
    EXPECT_LT((tethered.col(i) - expected).norm(), 1e-14);
  }
  // Still counter-clockwise (the constructor checks) and with the same area up to the
  // spline change: natural ends at the tether (zero curvature, thesis A.31-A.32) follow the
  // smooth ellipse less closely near node 0 than the periodic spline (2e-4 at 40 points).
  contour::ContourOptions options;
  options.closure = contour::Closure::Tethered;
  const contour::Contour c(tethered, options);
  EXPECT_NEAR(contour::enclosedArea(c), contour::enclosedArea(contour::Contour(nodes)), 5e-4);
}

TEST(TetherProcedure2D, PreparationEndsWhenTheShapeStopsChangingOrAtTheLatest)
{
  TetherSettings2D s;
  s.preparationTolerance = 1e-3;
  s.minimumPreparationTime = 0.5;
  s.maximumPreparationTime = 20.0;
  EXPECT_FALSE(preparationComplete(s, 0.2, 0.0));  // too early, even if steady
  EXPECT_FALSE(preparationComplete(s, 3.0, 2e-3)); // still deforming
  EXPECT_TRUE(preparationComplete(s, 3.0, -2e-3)); // past the maximum: relaxing
  EXPECT_TRUE(preparationComplete(s, 3.0, 5e-4));
  EXPECT_TRUE(preparationComplete(s, 3.0, -5e-4));
  EXPECT_TRUE(preparationComplete(s, 20.0, 1.0)); // the maximum time
}

TEST(TetherProcedure2D, PreparationChecksLandOnMultiplesOfTheWindow)
{
  TetherSettings2D s;
  s.preparationWindow = 0.25;
  EXPECT_DOUBLE_EQ(nextPreparationCheck(s, 0.0), 0.25);
  EXPECT_DOUBLE_EQ(nextPreparationCheck(s, 0.3), 0.5);
  // A time that landed on a check up to round-off is not checked again.
  EXPECT_DOUBLE_EQ(nextPreparationCheck(s, 0.5 * (1.0 - 1e-14)), 0.75);
  EXPECT_DOUBLE_EQ(nextPreparationCheck(s, 0.5), 0.75);
}

TEST(TetherProcedure2D, PredictedEndIsWhereTheExtrapolatedRateReachesTheTolerance)
{
  TetherSettings2D s;
  s.preparationWindow = 0.25;
  s.preparationTolerance = 1e-3;
  // D12 = c - 0.004 (tau - 4.95)^2: the window means of the rate are exact at the window
  // midpoints for a quadratic, so the extrapolated crossing of rate = 1e-3, at
  // tau = 4.95 - 1e-3 / 0.008 = 4.825, is exact (to round-off, 1e-12).
  const auto d12 = [](double tau) { return 0.7 - 0.004 * (tau - 4.95) * (tau - 4.95); };
  const auto rate = [&](double tau) { return (d12(tau) - d12(tau - 0.25)) / 0.25; };
  EXPECT_NEAR(predictedPreparationEnd(s, 4.75, rate(4.5), rate(4.75)), 4.825, 1e-12);
  // At 4.5 the crossing (4.825) lies beyond the next check (4.75): not yet.
  EXPECT_LT(predictedPreparationEnd(s, 4.5, rate(4.25), rate(4.5)), 0.0);
  // Far from the tolerance (rate 0.5 >= 10 tolerances) nothing is extrapolated, however
  // the rate slows; growth that speeds up, or a rate already below the tolerance, neither.
  EXPECT_LT(predictedPreparationEnd(s, 0.5, 1.35, 0.5), 0.0);
  EXPECT_LT(predictedPreparationEnd(s, 3.0, 0.002, 0.004), 0.0);
  EXPECT_LT(predictedPreparationEnd(s, 3.0, 0.002, 0.0005), 0.0);
}
