#include "capsula/scene2d/TetherProcedure2D.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>

#include <cmath>

namespace capsula::scene2d {

void declareTetherParameters2D(Teuchos::ParameterList& tether)
{
  namespace core = capsula::core;
  const TetherSettings2D defaults;
  core::declareBool(tether, "Enabled", defaults.enabled,
                    "true: the thesis's procedure (Section 4.1): a free preparation stage, then the "
                    "lowest node is fixed at (0, Anchor height). false: the cell stays free all run.");
  core::declareReal(tether, "Anchor height", defaults.anchorHeight,
                    "y of the tether point; the thesis fixed it at (0, 0.005).", core::greaterThan(0.0));
  core::declareReal(tether, "Preparation tolerance", defaults.preparationTolerance,
                    "The preparation stage ends when d D12 / d tau (tau = k t / lambda), measured "
                    "over the last Preparation window, falls below this: the free cell has reached "
                    "its largest deformation (a shape that relaxes, rate < 0, ends it too).",
                    core::greaterThan(0.0));
  core::declareReal(tether, "Preparation window", defaults.preparationWindow,
                    "tau between the checks of the preparation stage; d D12 / d tau is the change of "
                    "D12 since the last check over this window (a fixed window, not a time step, so "
                    "that the check does not depend on the step size or the grid-scale noise). The "
                    "stage ends where this rate falls below Preparation tolerance (interpolated "
                    "from the last two windows when it is close).",
                    core::greaterThan(0.0));
  core::declareBool(tether, "Wait for a node at the bottom", defaults.waitForNodeAtBottom,
                    "true: once the preparation's shape criterion holds, go on until a node passes "
                    "the lowest point of the contour and tether that node (the tether is then the "
                    "contour's lowest point; the wait is at most one node passage). false: tether "
                    "the node nearest the bottom at once (up to half a segment off the lowest point). "
                    "docs/tether2d-results.md compares the two.");
  core::declareReal(tether, "Minimum preparation time", defaults.minimumPreparationTime,
                    "tau before which the preparation stage never ends.", core::atLeast(0.0));
  core::declareReal(tether, "Maximum preparation time", defaults.maximumPreparationTime,
                    "tau at which the preparation stage ends whatever the deformation rate.", core::atLeast(0.0));
  core::declareReal(tether, "Force transient", defaults.forceTransient,
                    "tau after tethering left out of summary.json's max.tether_force_after_transient "
                    "(max.tether_force takes every step). Right after tethering a fast mode next to "
                    "the tether relaxes within a few hundredths of tau; its force spike depends on the "
                    "resolution and can be the run's largest force on coarse contours "
                    "(docs/tether2d-results.md).",
                    core::atLeast(0.0));
  core::declareBool(tether, "Regrid at tethering", defaults.regrid,
                    "true: at tethering, place the markers again at new material points whose spacing "
                    "grows from the tether (h = H min(1, f + (1 - f) d / w), d the reference arc distance from it), "
                    "to resolve the thin film between the membrane and the wall next to the tether "
                    "(docs/tether2d-results.md); "
                    "the tether is then the lowest point of the spline. false: keep the free "
                    "cell's markers and tether the one nearest the bottom (the thesis).");
  core::declareReal(tether, "Spacing at the tether", defaults.grading.tetherSpacing,
                    "With Regrid at tethering: f, the marker spacing at the tether as a fraction of the far "
                    "spacing H (1: even markers). The spacing grows linearly from f H to H over Graded length; "
                    "H is what makes the N markers fill the contour.",
                    core::greaterThan(0.0));
  core::declareReal(tether, "Graded length", defaults.grading.gradedLength,
                    "With Regrid at tethering: w, the reference arc length on each side of the tether over "
                    "which the spacing grows from f H to H (the reference contour's length is 2 pi for the "
                    "unit circle).",
                    core::greaterThan(0.0));
  core::declareReal(tether, "Preparation regrid interval", defaults.preparationRegridInterval,
                    "With Regrid at tethering: also give the free cell new markers graded towards its "
                    "lowest point every this much tau of the preparation (at the first check of the "
                    "preparation window at or after each multiple), so that the gap under the free cell "
                    "stays resolved while the membrane tank-treads through it. 0: only at tethering.",
                    core::atLeast(0.0));
}

TetherSettings2D readTetherSettings2D(const Teuchos::ParameterList& tether)
{
  TetherSettings2D s;
  s.enabled = tether.get<bool>("Enabled");
  s.anchorHeight = tether.get<double>("Anchor height");
  s.preparationTolerance = tether.get<double>("Preparation tolerance");
  s.preparationWindow = tether.get<double>("Preparation window");
  s.waitForNodeAtBottom = tether.get<bool>("Wait for a node at the bottom");
  s.minimumPreparationTime = tether.get<double>("Minimum preparation time");
  s.maximumPreparationTime = tether.get<double>("Maximum preparation time");
  s.forceTransient = tether.get<double>("Force transient");
  s.regrid = tether.get<bool>("Regrid at tethering");
  s.grading.tetherSpacing = tether.get<double>("Spacing at the tether");
  s.grading.gradedLength = tether.get<double>("Graded length");
  s.preparationRegridInterval = tether.get<double>("Preparation regrid interval");
  core::require<core::InputError>(s.preparationRegridInterval == 0.0 || s.regrid,
                                  "Tether/Preparation regrid interval = ", s.preparationRegridInterval,
                                  " needs Tether/Regrid at tethering = true (the tether must be placed on the "
                                  "graded markers too).");
  core::require<core::InputError>(s.grading.tetherSpacing <= 1.0,
                                  "Tether/Spacing at the tether must be <= 1 "
                                  "(a fraction of the far spacing), got ",
                                  s.grading.tetherSpacing);
  core::require<core::InputError>(s.minimumPreparationTime <= s.maximumPreparationTime,
                                  "Tether/Minimum preparation time (", s.minimumPreparationTime,
                                  ") exceeds Tether/Maximum preparation time (", s.maximumPreparationTime,
                                  "): lower the first or raise the second.");
  return s;
}

bool preparationComplete(const TetherSettings2D& settings, double tau, double deformationRate)
{
  if (tau >= settings.maximumPreparationTime) {
    return true;
  }
  return tau >= settings.minimumPreparationTime && deformationRate < settings.preparationTolerance;
}

double nextPreparationCheck(const TetherSettings2D& settings, double tau)
{
  // The tolerance keeps a time that landed on a check (up to round-off) from being
  // checked twice.
  const double w = settings.preparationWindow;
  return (std::floor(tau / w + 1e-9) + 1.0) * w;
}

double predictedPreparationEnd(const TetherSettings2D& settings, double tau, double previousRate, double rate)
{
  const double tolerance = settings.preparationTolerance;
  // Only a slowing growth that is already within 10 tolerances: far from the end, a line
  // through two window rates of an exponential approach (rate ~ e^{-tau/T}) would predict
  // a crossing much too early (it did at lambda = 10: 0.68 instead of > 1).
  if (!(previousRate > rate && rate > tolerance && rate < 10.0 * tolerance)) {
    return -1.0;
  }
  const double w = settings.preparationWindow;
  const double crossing = tau - 0.5 * w + w * (rate - tolerance) / (previousRate - rate);
  return crossing <= tau + w ? crossing : -1.0;
}

LowestNodeSlope lowestNodeSlope(const contour::Contour& contour)
{
  const Eigen::Matrix2Xd& nodes = contour.nodes();
  LowestNodeSlope result;
  for (Eigen::Index i = 1; i < nodes.cols(); ++i) {
    if (nodes(1, i) < nodes(1, result.node)) {
      result.node = static_cast<int>(i);
    }
  }
  result.slope = contour.nodePoint(result.node).tangent.y();
  return result;
}

double predictedZeroCrossing(double tPrevious, double gPrevious, double t, double g)
{
  if (!(t > tPrevious) || gPrevious == g) {
    return -1.0;
  }
  const double crossing = t - g * (t - tPrevious) / (g - gPrevious);
  return crossing > t ? crossing : -1.0;
}

TetherPlacement2D tetherPlacement(const Eigen::Matrix2Xd& nodes, const Eigen::Vector2d& anchor)
{
  TetherPlacement2D placement;
  for (Eigen::Index i = 1; i < nodes.cols(); ++i) {
    if (nodes(1, i) < nodes(1, placement.lowestNode)) {
      placement.lowestNode = static_cast<int>(i);
    }
  }
  placement.shift = anchor - nodes.col(placement.lowestNode);
  return placement;
}

Eigen::Matrix2Xd relabelNodes(const Eigen::Matrix2Xd& nodes, int offset)
{
  const Eigen::Index n = nodes.cols();
  Eigen::Matrix2Xd result(2, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    result.col(i) = nodes.col(((i + offset) % n + n) % n);
  }
  return result;
}

Eigen::Matrix2Xd tetheredNodes(const Eigen::Matrix2Xd& nodes, const TetherPlacement2D& placement)
{
  Eigen::Matrix2Xd shifted = nodes.colwise() + placement.shift;
  return relabelNodes(shifted, placement.lowestNode);
}

} // namespace capsula::scene2d
