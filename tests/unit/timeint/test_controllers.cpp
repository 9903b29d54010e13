// Step-size controllers: the thesis rule (eq 3.50) at its thresholds, and the PI controller.
#include "capsula/core/Error.hpp"
#include "capsula/timeint/StepControllers.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace ti = capsula::timeint;

namespace {
/// The error estimate that gives s = ratio in eq 3.50: s = (eps/2 / err)^(1/4).
double errorForRatio(double eps, double ratio)
{
  return 0.5 * eps / std::pow(ratio, 4);
}
// Relative offsets from the thresholds: far above the ~1e-16 rounding of s.
constexpr double above = 1.0 + 1e-9;
constexpr double below = 1.0 - 1e-9;
} // namespace

TEST(ThesisStepController, StepRatioIsEquation350)
{
  const ti::ThesisStepController c(1e-10);
  EXPECT_NEAR(c.stepRatio(0.5e-10 / 16.0), 2.0, 1e-15);
  EXPECT_TRUE(std::isinf(c.stepRatio(0.0)));
}

TEST(ThesisStepController, DoublesExactlyAboveRatioOnePointFive)
{
  const double eps = 1e-10, h = 0.01;
  const ti::ThesisStepController c(eps);
  const auto grow = c.decide(h, errorForRatio(eps, 1.5 * above), false);
  EXPECT_TRUE(grow.accepted);
  EXPECT_EQ(grow.nextStep, 2.0 * h);
  const auto keep = c.decide(h, errorForRatio(eps, 1.5 * below), false);
  EXPECT_TRUE(keep.accepted);
  EXPECT_EQ(keep.nextStep, h);
}

TEST(ThesisStepController, HalvesExactlyBelowRatioZeroPointSevenFive)
{
  const double eps = 1e-6, h = 0.25;
  const ti::ThesisStepController c(eps);
  const auto keep = c.decide(h, errorForRatio(eps, 0.75 * above), false);
  EXPECT_TRUE(keep.accepted);
  EXPECT_EQ(keep.nextStep, h);
  const auto halve = c.decide(h, errorForRatio(eps, 0.75 * below), false);
  EXPECT_FALSE(halve.accepted); // retried with half the step
  EXPECT_EQ(halve.nextStep, 0.5 * h);
  // The largest accepted error: eps / (2 * 0.75^4) = 1.58 eps.
  EXPECT_TRUE(c.decide(h, 1.58 * eps, false).accepted);
  EXPECT_FALSE(c.decide(h, 1.59 * eps, false).accepted);
}

TEST(ThesisStepController, DoesNotGrowRightAfterARejectionAndRejectsNaN)
{
  const double eps = 1e-6, h = 0.1;
  const ti::ThesisStepController c(eps);
  const auto d = c.decide(h, errorForRatio(eps, 3.0), true);
  EXPECT_TRUE(d.accepted);
  EXPECT_EQ(d.nextStep, h);
  EXPECT_FALSE(c.decide(h, std::nan(""), false).accepted);
  EXPECT_THROW(ti::ThesisStepController(0.0), capsula::core::InputError);
}

TEST(PiStepController, AcceptedStepFollowsThePiFormula)
{
  const ti::PiStepController c(5);
  const auto& p = c.parameters();
  const double h = 0.2, err = 0.3, previous = 0.6;
  const auto d = c.decide(h, err, previous, false);
  EXPECT_TRUE(d.accepted);
  // h * 0.9 * err^-0.17 * previous^0.04, to rounding.
  EXPECT_NEAR(d.nextStep, h * p.safety * std::pow(err, -p.alpha) * std::pow(previous, p.beta), 1e-15);
  // The proportional part: the same error after a larger previous error allows a larger
  // step (the error is falling), after a smaller one a smaller step.
  EXPECT_GT(c.decide(h, err, 0.9, false).nextStep, c.decide(h, err, 0.1, false).nextStep);
  // Smaller error, larger step.
  EXPECT_GT(c.decide(h, 0.01, previous, false).nextStep, d.nextStep);
}

TEST(PiStepController, ClampsAndRejects)
{
  const ti::PiStepController c(5);
  const double h = 1.0;
  EXPECT_EQ(c.decide(h, 0.0, 1.0, false).nextStep, 10.0 * h); // growth capped
  EXPECT_LE(c.decide(h, 1e-3, 0.5, true).nextStep, h);        // no growth after a rejection
  const auto reject = c.decide(h, 2.0, 0.5, false);
  EXPECT_FALSE(reject.accepted);
  EXPECT_NEAR(reject.nextStep, h * 0.9 * std::pow(2.0, -0.2), 1e-15);
  const auto hard = c.decide(h, 1e12, 0.5, false);
  EXPECT_FALSE(hard.accepted);
  EXPECT_EQ(hard.nextStep, 0.2 * h); // shrink capped
  EXPECT_EQ(c.decide(h, std::nan(""), 0.5, false).nextStep, 0.2 * h);
  EXPECT_EQ(c.rememberedError(1e-9), 1e-4);
}
