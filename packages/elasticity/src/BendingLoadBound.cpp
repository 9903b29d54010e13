#include "capsula/elasticity/BendingLoadBound.hpp"

#include <capsula/core/Error.hpp>

#include <algorithm>
#include <cmath>

namespace capsula::elasticity {

double bendingLoadScale(double modulus, double spontaneousCurvature, double shapeCurvature, double capillaryNumber)
{
  const double curvature = std::abs(spontaneousCurvature) + shapeCurvature;
  return modulus * curvature * curvature * curvature / capillaryNumber;
}

void requireRepresentableBending(const BendingBoundInput& in)
{
  if (in.modulus == 0.0) {
    return;
  }
  const double scale = bendingLoadScale(in.modulus, in.spontaneousCurvature, in.shapeCurvature, in.capillaryNumber);
  if (std::isfinite(scale) && scale <= kBendingLoadScaleBound) {
    return;
  }
  const std::string where = core::message(
      " makes the bending loads of order E_b (|c0| + kappa)^3 / Ca = ", scale, " (kappa = ", in.shapeCurvature,
      ", the curvature of the cell's shape; Ca = '", in.capillaryKey, "' = ", in.capillaryNumber, "), beyond ",
      kBendingLoadScaleBound, ", where the run's arithmetic overflows: ");
  if (!in.curvatureKey.empty() && std::abs(in.spontaneousCurvature) > in.shapeCurvature) {
    const double largest = std::cbrt(kBendingLoadScaleBound * in.capillaryNumber / in.modulus) - in.shapeCurvature;
    throw core::InputError(core::message("'", in.curvatureKey, "' = ", in.spontaneousCurvature, where, "give |c0| <= ",
                                         std::max(0.0, largest), " (a sphere of radius R has c0 = 2/R)."));
  }
  const double curvature = std::abs(in.spontaneousCurvature) + in.shapeCurvature;
  const double largest = kBendingLoadScaleBound * in.capillaryNumber / (curvature * curvature * curvature);
  throw core::InputError(core::message("'", in.modulusKey, "' = ", in.modulus, where, "give a modulus <= ", largest,
                                       in.curvatureKey.empty() ? "." : " (a red cell's is 0.005-0.03)."));
}

} // namespace capsula::elasticity
