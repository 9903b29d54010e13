#pragma once
// New markers graded towards the tether (an option of the tether procedure, Tether/Regrid
// at tethering and Preparation regrid interval; docs/tether2d.md).
//
// Why: at the thesis's anchor height 0.005 the membrane next to the tether and under the
// free cell runs within 0.005-0.1 of the wall, much closer than the spacing of 256 even
// markers, and the tether force does not converge under uniform refinement up to 1024
// points. Markers graded towards the tether (and the free cell's towards its lowest point)
// put the resolution there: with the thesis's unstressed membrane they cut the spread of
// F_max over 64-512 points from 4.5% to 1.3% but do not make it converge (the free cell's
// compressed membrane wrinkles at the grid scale); with Cell/Prestress = 0.2 F_max converges
// to 0.1% from 128 graded points on (docs/tether2d-results.md has both studies).
//
// How: at the end of the free preparation stage the contour is sampled again at N new
// material points. Their reference arc lengths, measured from the material point at the
// lowest point of the spline (the new tether), have the spacing
//   h(d) = H min(1, f + (1 - f) d / w),   d = reference arc distance from the tether,
// on both sides: f H at the tether (f = Spacing at the tether), growing linearly to the far
// spacing H over the reference arc length w (Graded length), and H chosen so that exactly
// N markers fill L0. The shape of h is fixed and only H scales like 1/N, so contours of
// different N are refinements of one grid family (a mesh-convergence study stays one).
// Each new marker's current position comes from the free cell's own splines: l(l0)
// (MaterialArcLength2D) then the point at arc length l, so the shape, the stretch and the
// tension are those of the free cell up to the splines' O(h^4) interpolation error; its
// reference position is the point at arc length l0 on the reference contour. The tether is
// the lowest point of the spline itself, not the nearest of the old markers.
#include <capsula/contour/Contour.hpp>

#include <Eigen/Core>

#include <vector>

namespace capsula::scene2d {

struct TetherGrading2D {
  double tetherSpacing = 0.1; ///< f: the spacing at the tether as a fraction of the far spacing H
  double gradedLength = 1.0;  ///< w: the reference arc length over which it grows to H
};

/// Reference arc lengths sigma_0 = 0 < sigma_1 < ... < sigma_N = length of N markers
/// spaced as above from the tether at 0 (= length); symmetric, sigma_{N-j} = length -
/// sigma_j. Throws InputError unless 0 < f <= 1 (f = 1: even spacing) and w > 0.
std::vector<double> gradedArcLengths(int markers, double length, const TetherGrading2D& grading);

struct TetherRegrid2D {
  Eigen::Matrix2Xd referenceNodes;       ///< node 0 is the tether's material point; counter-clockwise
  Eigen::Matrix2Xd currentNodes;         ///< the same material points now (regridAtTether: node 0 at the anchor)
  double tetherArcLength = 0.0;          ///< l of the lowest point on the free contour
  double tetherReferenceArcLength = 0.0; ///< its l0 on the reference contour
};

/// Samples the free cell `current` (periodic, same markers as the periodic `reference`) at
/// numberOfNodes() new material points graded towards its lowest point (node 0), where it
/// is: the free cell's markers during the preparation (Tether/Preparation regrid interval).
TetherRegrid2D regridTowardsLowestPoint(const contour::Contour& reference, const contour::Contour& current,
                                        const TetherGrading2D& grading);

/// The same, shifted so that the lowest point is at `anchor`: the tethered cell's markers.
TetherRegrid2D regridAtTether(const contour::Contour& reference, const contour::Contour& current,
                              const TetherGrading2D& grading, const Eigen::Vector2d& anchor);

} // namespace capsula::scene2d
