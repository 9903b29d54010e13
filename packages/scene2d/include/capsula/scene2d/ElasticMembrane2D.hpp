#pragma once
// Elastic tension and load of a 2D membrane (thesis A.5).
//
// The markers are material points, so the stretch ratio omega = dl/dl0 (eq A.37) is
// the derivative of a spline of the current arc length l at the nodes against the
// reference arc length l0 at the same nodes (eq A.38); both arc lengths are true spline
// arc lengths (Gauss-Legendre), not chords. The tension gamma = E (omega - 1) at the
// nodes (the law's, MembraneLaw2D.hpp; Hookean: E (omega - 1)) is splined against l, whose
// derivative gives d gamma / dl (eq A.39), and the load
// is Delta f = gamma kappa n - (d gamma / dl) t (eq A.4, sign: MembraneLoad2D.hpp).
//
// End conditions of these two auxiliary splines: periodic for a free cell. For a tethered
// contour the thesis leaves them open; natural ends would force d omega/dl0 = 0 and
// d^2 gamma/dl^2 = 0 at the tether, which nothing in the mechanics imposes, so they use
// not-a-knot ends (exact for cubics, no end data needed); MaterialArcLength2D.hpp builds
// l(l0).
//
// A membrane built with a bending law adds the bending load (MembraneBending2D.hpp) to the
// tension's in every evaluation; one built without has no bending term at all.
#include "capsula/scene2d/HookeanLaw2D.hpp"
#include "capsula/scene2d/MembraneBending2D.hpp"
#include "capsula/scene2d/MembraneLaw2D.hpp"
#include "capsula/scene2d/MembraneState2D.hpp"

#include <capsula/contour/Contour.hpp>

#include <memory>
#include <optional>
#include <vector>

namespace capsula::scene2d {

class ElasticMembrane2D {
public:
  /// `reference` is the unstressed contour (its marker points are the same material
  /// points as those of every contour later passed to evaluate()). Throws core::Error
  /// for a null law.
  ElasticMembrane2D(const contour::Contour& reference, std::shared_ptr<const MembraneLaw2D> law);
  /// With bending stiffness as well (kappa_ref from `reference` with 'Initial shape').
  ElasticMembrane2D(const contour::Contour& reference, std::shared_ptr<const MembraneLaw2D> law, BendingLaw2D bending);
  /// The Hookean law of the thesis's model (eq A.36).
  ElasticMembrane2D(const contour::Contour& reference, const HookeanLaw2D& law);
  ElasticMembrane2D(const contour::Contour& reference, const HookeanLaw2D& law, BendingLaw2D bending);

  const MembraneLaw2D& law() const { return *law_; }
  /// The bending part, or null without one.
  const MembraneBending2D* bending() const { return bending_ ? &*bending_ : nullptr; }
  /// Reference arc length l0 at the knots, 0 .. L0 (N + 1 values).
  const std::vector<double>& referenceArcLengths() const { return referenceArcLengths_; }
  int numberOfNodes() const { return static_cast<int>(referenceArcLengths_.size()) - 1; }

  /// Stretch, tension and load on `current`. Throws InputError unless it has the
  /// reference's number of nodes and closure.
  MembraneState2D evaluate(const contour::Contour& current) const;

private:
  std::shared_ptr<const MembraneLaw2D> law_;
  contour::Closure closure_;
  std::vector<double> referenceArcLengths_;
  std::optional<MembraneBending2D> bending_;
};

} // namespace capsula::scene2d
