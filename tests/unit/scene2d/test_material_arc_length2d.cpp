// The material map l(l0) of a 2D membrane (MaterialArcLength2D): exact for uniform stretch,
// its inverse, and the periodic continuation past L0.
#include "capsula/testing/Constants.hpp"
#include <capsula/contour/Contour.hpp>
#include <capsula/contour/InitialShapes.hpp>
#include <capsula/scene2d/MaterialArcLength2D.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using capsula::testing::pi;

using namespace capsula;

TEST(MaterialArcLength2D, UniformStretchIsLinearAndInvertible)
{
  // The unit circle stretched to radius 1.5 through the same markers: l = 1.5 l0 exactly
  // (the periodic part vanishes to round-off), omega = 1.5 everywhere.
  const contour::Contour reference(contour::circleNodes(32, 1.0));
  const contour::Contour current(contour::circleNodes(32, 1.5));
  const scene2d::MaterialArcLength2D map(reference.knotArcLengths(), current.knotArcLengths(),
                                         contour::Closure::Periodic);
  EXPECT_NEAR(map.meanStretch(), 1.5, 1e-14);
  for (const double l0 : {0.0, 0.7, 3.1, 6.0}) {
    EXPECT_NEAR(map.currentArcLength(l0), 1.5 * l0, 1e-12) << l0;
    EXPECT_NEAR(map.stretch(l0), 1.5, 1e-12) << l0;
    EXPECT_NEAR(map.referenceArcLength(1.5 * l0), l0, 1e-12) << l0;
  }
  // Past L0 by one period, l moves on by one current length.
  EXPECT_NEAR(map.currentArcLength(reference.length() + 0.7), current.length() + 1.5 * 0.7, 1e-12);
}

TEST(MaterialArcLength2D, NonUniformStretchRoundTrips)
{
  // Markers moved along the circle by x -> x + 0.2 sin(x) in angle: the stretch is
  // 1 + 0.2 cos(theta0), so l(l0) = l0 + 0.2 sin(l0) on the unit circle (to the spline's
  // O(h^4): 1e-6 at 64 markers); l0(l(l0)) = l0 to Newton's round-off.
  const int n = 64;
  Eigen::Matrix2Xd moved(2, n);
  for (int i = 0; i < n; ++i) {
    const double theta0 = 2.0 * pi * i / n;
    const double theta = theta0 + 0.2 * std::sin(theta0);
    moved.col(i) = Eigen::Vector2d(std::cos(theta), std::sin(theta));
  }
  const contour::Contour reference(contour::circleNodes(n, 1.0));
  const contour::Contour current(moved);
  const scene2d::MaterialArcLength2D map(reference.knotArcLengths(), current.knotArcLengths(),
                                         contour::Closure::Periodic);
  for (const double l0 : {0.05, 1.3, 2.9, 4.4, 6.1}) {
    EXPECT_NEAR(map.currentArcLength(l0), l0 + 0.2 * std::sin(l0), 1e-5) << l0;
    EXPECT_NEAR(map.stretch(l0), 1.0 + 0.2 * std::cos(l0), 1e-4) << l0;
    EXPECT_NEAR(map.referenceArcLength(map.currentArcLength(l0)), l0, 1e-12) << l0;
  }
}

TEST(MaterialArcLength2D, StronglyVaryingStretchOnATetheredContourInverts)
{
  // l(l0) = l0 + 0.9 sin(l0) on [0, 2 pi]: the stretch 1 + 0.9 cos(l0) goes from 1.9 down to
  // 0.1, where plain Newton from l L0 / L overshoots; the safeguarded inverse must still
  // return l0 to round-off, up to the ends of a tethered (open, not-a-knot) contour.
  const int n = 64;
  std::vector<double> l0(n + 1), l(n + 1);
  for (int i = 0; i <= n; ++i) {
    l0[i] = 2.0 * pi * i / n;
    l[i] = l0[i] + 0.9 * std::sin(l0[i]);
  }
  const scene2d::MaterialArcLength2D map(l0, l, contour::Closure::Tethered);
  for (const double x : {0.0, 1e-9, 0.4, 2.9, pi, 3.3, 5.0, 2.0 * pi - 1e-9, 2.0 * pi}) {
    EXPECT_NEAR(map.referenceArcLength(map.currentArcLength(x)), x, 1e-12) << x;
  }
  // The spline itself follows l0 + 0.9 sin(l0) to its O(h^4) error.
  EXPECT_NEAR(map.currentArcLength(pi + 0.05), pi + 0.05 + 0.9 * std::sin(pi + 0.05), 1e-5);
}
