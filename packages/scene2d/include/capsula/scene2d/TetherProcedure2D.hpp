#pragma once
// The tether procedure of thesis Section 4.1.
//
// Tethering the reference cell at t = 0 was unstable in the thesis (a sawtooth buckling
// upstream of the tether), so the cell first moves freely with its lowest point at the
// gap above the wall (the preparation stage) and "deforms to its maximum extent". Here
// that extent is reached when the Taylor deformation D12 stops growing. D12 is sampled at
// tau = W, 2W, 3W, ... (W = Preparation window; tau = k t / lambda, eq 4.1; the integrator
// lands on these times), and r_k = (D12(tau_k) - D12(tau_k - W)) / W, the mean rate over
// the window, approximates d D12 / d tau at tau_k - W / 2. The stage ends, after
// tau >= Minimum preparation time, when the rate falls below Preparation tolerance
// (signed: a shape that has passed its maximum and relaxes ends it too): at the check where
// r_k < tolerance, or, when the growth slows (r_{k-1} > r_k) and r_k is within 10
// tolerances, at the tau where the line through the last two window rates crosses the
// tolerance if that falls before the next check (the integrator lands there, so the end
// time is a continuous function of the solution rather than a multiple of W); or at
// tau = Maximum preparation time. Then the node nearest the bottom is tethered. With Wait
// for a node at the bottom = true the run goes on instead until a node passes through the
// lowest point of the contour (the tank-treading membrane carries the nodes past it; the
// integrator lands on the predicted zero of the tangent's y at the lowest node), so that
// the tether is the lowest point of the spline and the force right after tethering is
// nearly along x (|F_y| / F < 0.1 against up to 0.44). It is off by default: the wait, up to
// one node passage (0.42 tau at 48 points near the wall, shrinking like 1/N), shifts the
// tethering time by O(1/N), and the converging global quantities showed it (anchor 0.1,
// maximum cell length from 128 to 192 to 256 points: 8.6e-4 and 1.9e-4 apart without the
// wait, 2.0e-3 and 2.8e-3 with it).
// Near the wall at the thesis's gap 0.005 a free capsule first elongates (D12 = 0.722 at
// tau = 5 for a/b = 1, Ca = 0.25, lambda = 1), then lifts off the wall and relaxes to the
// lower unbounded value (D12 = 0.61 at tau = 15, 1.3 above the wall): the rate crosses the
// tolerance just before that maximum, the thesis's "maximum extent". The rate is a
// difference over a fixed window of tau, not over one time step: the step-to-step rate
// carries the grid-scale noise of the near-wall region (it falls below 1e-3 for one step at
// tau = 4.74 with 64 points and 4.94 with 128 while D12 still grows by 0.01 per tau) and
// would end the stage at a resolution-dependent, noise-picked time. The tether node is moved
// with the whole contour to the anchor (0, Anchor height) and relabelled node 0 (a cyclic
// relabelling keeps the nodes counter-clockwise), the contour becomes a tethered spline,
// the tether node's velocity is held at zero, and time restarts: tau = k (t - t0) / lambda.
#include "capsula/scene2d/TetherRegrid2D.hpp"

#include <capsula/contour/Contour.hpp>

#include <Eigen/Core>
#include <Teuchos_ParameterList.hpp>

namespace capsula::scene2d {

struct TetherSettings2D {
  bool enabled = true;
  double anchorHeight = 0.005;          ///< anchor at (0, anchorHeight)
  double preparationTolerance = 1.0e-3; ///< on |d D12 / d tau|
  double preparationWindow = 0.05;      ///< tau over which d D12 / d tau is measured
  bool waitForNodeAtBottom = false;     ///< then tether when a node passes the lowest point
  double minimumPreparationTime = 0.5;  ///< tau
  double maximumPreparationTime = 20.0; ///< tau
  /// tau after tethering that max.tether_force_after_transient leaves out (the fast
  /// relaxation next to the tether, ~0.01 tau, whose spike depends on the resolution).
  double forceTransient = 0.1;
  /// New markers graded towards the tether at tethering (TetherRegrid2D.hpp).
  bool regrid = false;
  TetherGrading2D grading;
  /// With regrid: also regrid the free cell every this much tau of the preparation (0: never).
  double preparationRegridInterval = 0.0;
};

/// Declares Enabled, Anchor height, Preparation tolerance, Preparation window, Wait for a
/// node at the bottom, Minimum preparation time, Maximum preparation time and Force
/// transient in `tether`.
void declareTetherParameters2D(Teuchos::ParameterList& tether);

/// Reads a validated "Tether" sublist; throws core::InputError if the minimum
/// preparation time exceeds the maximum.
TetherSettings2D readTetherSettings2D(const Teuchos::ParameterList& tether);

/// Whether the preparation stage is over at the check time tau (a multiple of the window)
/// with the deformation rate (D12(tau) - D12(tau - window)) / window: tau is past the
/// maximum preparation time, or past the minimum with a rate below the tolerance (signed).
bool preparationComplete(const TetherSettings2D& settings, double tau, double deformationRate);

/// The first preparation check time (a multiple of settings.preparationWindow) after tau.
double nextPreparationCheck(const TetherSettings2D& settings, double tau);

/// The tau at which the window rate is predicted to fall to the tolerance, from the rates
/// of this check (rate, at tau) and the previous one: the crossing of the line through
/// (tau - 3W/2, previousRate) and (tau - W/2, rate), if the growth slows
/// (previousRate > rate), tolerance < rate < 10 tolerance, and the crossing falls no later
/// than the next check tau + W; otherwise a negative number.
double predictedPreparationEnd(const TetherSettings2D& settings, double tau, double previousRate, double rate);

/// The lowest node of a contour and the y-component of the unit tangent there (zero when
/// the node is the lowest point of the spline).
struct LowestNodeSlope {
  int node = 0;
  double slope = 0.0;
};
LowestNodeSlope lowestNodeSlope(const contour::Contour& contour);

/// The time at which a quantity sampled as gPrevious at tPrevious and g at t reaches zero on
/// the line through the two samples, if that is after t; otherwise a negative number.
double predictedZeroCrossing(double tPrevious, double gPrevious, double t, double g);

/// Where a contour is tethered: its lowest node and the shift that takes it to the anchor.
struct TetherPlacement2D {
  int lowestNode = 0;
  Eigen::Vector2d shift = Eigen::Vector2d::Zero();
};

/// The node with the smallest y (the first one on a tie) and the shift to `anchor`.
TetherPlacement2D tetherPlacement(const Eigen::Matrix2Xd& nodes, const Eigen::Vector2d& anchor);

/// Node i of the result is node (i + offset) mod N of `nodes`.
Eigen::Matrix2Xd relabelNodes(const Eigen::Matrix2Xd& nodes, int offset);

/// `nodes` shifted by placement.shift and relabelled so that the lowest node is node 0.
Eigen::Matrix2Xd tetheredNodes(const Eigen::Matrix2Xd& nodes, const TetherPlacement2D& placement);

} // namespace capsula::scene2d
