#include "capsula/scene2d/ElasticMembrane2D.hpp"

#include "capsula/scene2d/MaterialArcLength2D.hpp"
#include "capsula/scene2d/MembraneLoad2D.hpp"

#include <capsula/contour/CubicSpline.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/quadrature/GaussLegendre.hpp>

#include <cstddef>
#include <utility>

namespace capsula::scene2d {

using contour::Closure;
using contour::Contour;
using contour::CubicSpline;

ElasticMembrane2D::ElasticMembrane2D(const Contour& reference, std::shared_ptr<const MembraneLaw2D> law)
    : law_(std::move(law)), closure_(reference.closure()), referenceArcLengths_(reference.knotArcLengths())
{
  core::require(law_ != nullptr, "ElasticMembrane2D: no membrane law");
}

ElasticMembrane2D::ElasticMembrane2D(const Contour& reference, std::shared_ptr<const MembraneLaw2D> law,
                                     BendingLaw2D bending)
    : ElasticMembrane2D(reference, std::move(law))
{
  bending_.emplace(reference, bending);
}

ElasticMembrane2D::ElasticMembrane2D(const Contour& reference, const HookeanLaw2D& law)
    : ElasticMembrane2D(reference, std::make_shared<const HookeanLaw2D>(law))
{}

ElasticMembrane2D::ElasticMembrane2D(const Contour& reference, const HookeanLaw2D& law, BendingLaw2D bending)
    : ElasticMembrane2D(reference, std::make_shared<const HookeanLaw2D>(law), bending)
{}

MembraneState2D ElasticMembrane2D::evaluate(const Contour& current) const
{
  const int n = numberOfNodes();
  core::require<core::InputError>(current.numberOfNodes() == n, "the deformed contour has ", current.numberOfNodes(),
                                  " nodes but the membrane's reference has ", n,
                                  "; markers must be the same material points");
  core::require<core::InputError>(current.closure() == closure_,
                                  "the deformed contour and the membrane's reference must be both "
                                  "periodic or both tethered");
  const auto nodes = static_cast<std::size_t>(n);
  const std::vector<double>& l0 = referenceArcLengths_;
  const std::vector<double>& l = current.knotArcLengths();

  // Stretch spline l(l0) (eq A.38); omega at the knots is its slope there.
  const MaterialArcLength2D material(l0, l, closure_);
  const CubicSpline& stretchSpline = material.spline();
  const double meanStretch = material.meanStretch(); // the non-periodic part of dl/dl0 on a free cell
  std::vector<double> omega(nodes + 1);
  for (std::size_t i = 0; i < nodes; ++i) {
    omega[i] = meanStretch + stretchSpline.piece(static_cast<int>(i)).c;
  }
  omega[nodes] = meanStretch + stretchSpline.piece(n - 1).derivative(l0[nodes] - l0[nodes - 1]);

  // Energy int w(omega) dl0: omega is quadratic in l0 on each piece, so three Gauss points
  // integrate the Hookean law's quartic 0.5 E (omega - 1)^2 exactly.
  const quadrature::Rule1D rule = quadrature::gaussLegendre(3);
  double energy = 0.0;
  for (std::size_t k = 0; k < nodes; ++k) {
    const double span = l0[k + 1] - l0[k];
    const contour::CubicPiece& piece = stretchSpline.piece(static_cast<int>(k));
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const double stretch = meanStretch + piece.derivative(rule.points[q] * span);
      energy += rule.weights[q] * span * law_->energyDensity(stretch);
    }
  }

  // Tension at the knots (the law's; Hookean: eq A.36) and its spline in the current arc length (eq A.39).
  std::vector<double> gamma(nodes + 1);
  for (std::size_t i = 0; i <= nodes; ++i) {
    gamma[i] = law_->tension(omega[i]);
  }
  CubicSpline tensionSpline = [&] {
    if (closure_ == Closure::Periodic) {
      gamma.pop_back();
      return CubicSpline::periodic(l, gamma);
    }
    return CubicSpline::notAKnot(l, gamma);
  }();

  MembraneState2D state(current, std::move(tensionSpline));
  if (bending_) {
    state.bending_.emplace(bending_->evaluate(current));
  }
  state.stretch_.resize(n);
  state.tension_.resize(n);
  state.tensionSlope_.resize(n);
  state.load_.resize(2, n);
  for (int i = 0; i < n; ++i) {
    const contour::CubicPiece& piece = state.tensionSpline_.piece(i);
    state.stretch_(i) = omega[static_cast<std::size_t>(i)];
    state.tension_(i) = piece.d;
    state.tensionSlope_(i) = piece.c;
    state.load_.col(i) = membraneLoad2D(piece.d, piece.c, current.nodePoint(i));
  }
  if (bending_) {
    state.load_ += state.bending_->load();
  }
  state.energy_ = energy;
  return state;
}

} // namespace capsula::scene2d
