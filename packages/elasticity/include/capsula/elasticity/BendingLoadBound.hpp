#pragma once
// The largest bending a run can represent. The bending load on a membrane is of order
// E_b (|c0| + kappa)^3 (moduli in the capillary number's G, lengths in cell radii, kappa the
// curvature of the cell's own shape), and the velocity it drives of order that over Ca. The
// step-size control squares such numbers and sums them over the nodes, so a load scale
// beyond kBendingLoadScaleBound overflows the doubles (1.8e308) in the first steps: the run
// fails with "not finite" at t = 0. At 1e100 the square, summed over a million nodes, stays
// 1e100 below the largest double, room for a shape's corners sharper than kappa; a red
// cell's bending (E_b ~ 0.03, c0 ~ 1) has a load scale near 1.
#include <string>

namespace capsula::elasticity {

constexpr double kBendingLoadScaleBound = 1e100;

/// E_b (|c0| + kappa)^3 / Ca: the scale of the bending load's velocity.
double bendingLoadScale(double modulus, double spontaneousCurvature, double shapeCurvature, double capillaryNumber);

/// The keys and scene values a bending bound is checked against.
struct BendingBoundInput {
  double modulus = 0.0;
  double spontaneousCurvature = 0.0;
  double shapeCurvature = 1.0; ///< kappa: the largest curvature of the cell's shape, 1 / its smallest semi-axis
  double capillaryNumber = 1.0;
  std::string modulusKey;   ///< e.g. "Cells/Cell 0/Bending modulus"
  std::string curvatureKey; ///< e.g. "Cells/Cell 0/Spontaneous curvature"; empty where there is none (2D)
  std::string capillaryKey; ///< e.g. "Flow/Capillary number"
};

/// Throws core::InputError naming the key that makes the load scale exceed
/// kBendingLoadScaleBound (the spontaneous curvature where |c0| > kappa, else the modulus),
/// its value, and the largest value of it that stays within the bound.
void requireRepresentableBending(const BendingBoundInput& input);

} // namespace capsula::elasticity
