#pragma once
// The tether procedure of thesis Section 4.1.
//
// Tethering the reference cell at t = 0 was unstable in the thesis (a sawtooth buckling
// upstream of the tether), so the cell first moves freely with its lowest point at the
// gap above the wall (the preparation stage) and "deforms to its maximum extent". Here
// that extent is reached when the shape stops changing, measured by the Taylor deformation:
//   |d D12 / d tau| < Preparation tolerance  after  tau >= Minimum preparation time,
// tau = k t / lambda (the relaxation time scales with lambda, eq 4.1), checked after every
// accepted step that was not shortened to land on an output time; or at tau = Maximum
// preparation time, whichever comes first. (A free capsule in shear keeps tank-treading
// and drifting, so the nodes never stop; its shape does.) Then the lowest node is moved
// with the whole contour to the anchor (0, Anchor height) and relabelled node 0 (a cyclic
// relabelling keeps the nodes counter-clockwise), the contour becomes a tethered spline,
// the tether node's velocity is held at zero, and time restarts: tau = k (t - t0) / lambda.
#include <Eigen/Core>
#include <Teuchos_ParameterList.hpp>

namespace capsula::scene2d {

struct TetherSettings2D {
  bool enabled = true;
  double anchorHeight = 0.005;           ///< anchor at (0, anchorHeight)
  double preparationTolerance = 1.0e-3;  ///< on |d D12 / d tau|
  double minimumPreparationTime = 0.5;   ///< tau
  double maximumPreparationTime = 20.0;  ///< tau
};

/// Declares Enabled, Anchor height, Preparation tolerance, Minimum preparation time and
/// Maximum preparation time in `tether`.
void declareTetherParameters2D(Teuchos::ParameterList& tether);

/// Reads a validated "Tether" sublist; throws core::InputError if the minimum
/// preparation time exceeds the maximum.
TetherSettings2D readTetherSettings2D(const Teuchos::ParameterList& tether);

/// Whether the preparation stage is over at tau with the deformation rate d D12 / d tau
/// of the last accepted (not shortened) step.
bool preparationComplete(const TetherSettings2D& settings, double tau, double deformationRate);

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
