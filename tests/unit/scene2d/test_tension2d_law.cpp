// The 2D Hookean law (eq A.36) and the load kernel (eq A.4): values, validation, sign.
#include <capsula/contour/Contour.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/scene2d/HookeanLaw2D.hpp>
#include <capsula/scene2d/MembraneLoad2D.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace {

namespace scene2d = capsula::scene2d;
using capsula::scene2d::HookeanLaw2D;

TEST(Tension2DLaw, TensionAndEnergyDensity)
{
  const HookeanLaw2D law(2.5);
  EXPECT_DOUBLE_EQ(law.modulus(), 2.5);
  EXPECT_DOUBLE_EQ(law.tension(1.0), 0.0);
  EXPECT_NEAR(law.tension(1.2), 0.5, 1e-15);
  EXPECT_NEAR(law.tension(0.9), -0.25, 1e-15); // compression: negative tension
  EXPECT_NEAR(law.energyDensity(1.2), 0.05, 1e-15);
  // d(energy density)/d(stretch) = tension: the pair is consistent (central difference,
  // exact for the quadratic up to round-off).
  const double h = 1e-4;
  EXPECT_NEAR((law.energyDensity(1.3 + h) - law.energyDensity(1.3 - h)) / (2.0 * h), law.tension(1.3), 1e-10);
}

TEST(Tension2DLaw, RejectsNonPositiveModulusNamingIt)
{
  for (double bad : {0.0, -1.0, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()}) {
    try {
      const HookeanLaw2D law(bad);
      ADD_FAILURE() << "accepted E = " << bad;
    } catch (const capsula::core::InputError& error) {
      EXPECT_NE(std::string(error.what()).find("modulus"), std::string::npos) << error.what();
    }
  }
}

TEST(Tension2DLaw, LoadKernelIsLaplaceOnACircleAndPullsAlongTheTensionGradient)
{
  // Circle of radius 2 at angle 0.3: kappa = 1/2, n = radial, t = counter-clockwise.
  const double angle = 0.3;
  const Eigen::Vector2d radial(std::cos(angle), std::sin(angle));
  const Eigen::Vector2d first = 2.0 * Eigen::Vector2d(-std::sin(angle), std::cos(angle));
  const Eigen::Vector2d second = -2.0 * radial;
  const capsula::contour::ContourPoint p = capsula::contour::contourPoint(2.0 * radial, first, second);
  // Uniform tension 3: Delta f = (gamma / R) n, pressure higher inside.
  const Eigen::Vector2d laplace = scene2d::membraneLoad2D(3.0, 0.0, p);
  EXPECT_NEAR((laplace - 1.5 * radial).norm(), 0.0, 1e-15);
  // Tension rising along t: the membrane pulls towards higher tension, so the load on the
  // fluid is -(d gamma/dl) t.
  const Eigen::Vector2d gradient = scene2d::membraneLoad2D(0.0, 0.7, p);
  EXPECT_NEAR((gradient + 0.7 * p.tangent).norm(), 0.0, 1e-15);
}

} // namespace
