#pragma once
// Bending stiffness of a 2D membrane: the moment m = k_b (kappa - kappa_ref) and its load on
// the fluids (BendingLoad2D.hpp), evaluated on deformed contours (BendingState2D.hpp).
//
// kappa_ref is attached to the material points (the markers): 0 for a membrane whose
// unstressed shape is flat, or the curvature of the reference contour at each marker
// ('Initial shape'), taken from the closed periodic spline through the reference nodes even
// when the contour is tethered (the reference shape is a smooth closed curve; a tethered
// spline's natural ends would make it 0 at the tether).
#include "capsula/scene2d/BendingState2D.hpp"

#include <capsula/contour/Contour.hpp>

#include <vector>

namespace capsula::scene2d {

enum class BendingReference2D {
  Flat,        ///< kappa_ref = 0
  InitialShape ///< kappa_ref = the reference contour's curvature at each material point
};

struct BendingLaw2D {
  double modulus = 0.0; ///< k_b, in E L^2 where the tension is in E
  BendingReference2D reference = BendingReference2D::Flat;
};

class MembraneBending2D {
public:
  /// `reference` holds the material points of every contour later passed to evaluate(), in
  /// the same order. Throws InputError unless the modulus is finite and >= 0.
  MembraneBending2D(const contour::Contour& reference, BendingLaw2D law);

  const BendingLaw2D& law() const { return law_; }
  /// kappa_ref at the knots: N values on a periodic reference, N + 1 on a tethered one (the
  /// last is node 0's again); empty when flat.
  const std::vector<double>& referenceCurvature() const { return referenceCurvature_; }

  /// Misfit, load and energy on `current`. Throws InputError unless it has the reference's
  /// number of nodes and closure.
  BendingState2D evaluate(const contour::Contour& current) const;

private:
  BendingLaw2D law_;
  contour::Closure closure_;
  int nodes_;
  std::vector<double> referenceCurvature_;
};

} // namespace capsula::scene2d
