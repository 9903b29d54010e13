#include "capsula/scene2d/MembraneBending2D.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/quadrature/GaussLegendre.hpp>

#include <cmath>
#include <cstddef>
#include <utility>

namespace capsula::scene2d {

using contour::Closure;
using contour::Contour;
using contour::CubicSpline;

namespace {

/// The spline of per-knot values against the knot arc lengths `l`, with the tension
/// spline's ends: periodic (N values) or not-a-knot (N + 1 values).
CubicSpline arcLengthSpline(const std::vector<double>& l, std::vector<double> values, Closure closure)
{
  if (closure == Closure::Periodic) {
    values.resize(l.size() - 1);
    return CubicSpline::periodic(l, values);
  }
  return CubicSpline::notAKnot(l, values);
}

/// kappa at the knots: N values, and for a tethered contour node 0's other side at s_max.
std::vector<double> knotCurvatures(const Contour& c)
{
  const int n = c.numberOfNodes();
  std::vector<double> kappa(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    kappa[static_cast<std::size_t>(i)] = c.nodePoint(i).curvature;
  }
  kappa.push_back(c.closure() == Closure::Periodic ? kappa.front() : c.pointAt(n - 1, 1.0).curvature);
  return kappa;
}

} // namespace

MembraneBending2D::MembraneBending2D(const Contour& reference, BendingLaw2D law)
    : law_(law), closure_(reference.closure()), nodes_(reference.numberOfNodes())
{
  core::require<core::InputError>(std::isfinite(law.modulus) && law.modulus >= 0.0,
                                  "the 2D membrane's bending modulus k_b is ", law.modulus,
                                  "; give k_b >= 0 (0: no bending stiffness)");
  if (law.reference == BendingReference2D::InitialShape) {
    // The closed reference shape's curvature at each marker (see the header).
    contour::ContourOptions options = reference.options();
    options.closure = Closure::Periodic;
    referenceCurvature_ = knotCurvatures(Contour(reference.nodes(), options));
    if (closure_ == Closure::Periodic) {
      referenceCurvature_.pop_back();
    }
  }
}

BendingState2D MembraneBending2D::evaluate(const Contour& current) const
{
  core::require<core::InputError>(current.numberOfNodes() == nodes_, "the deformed contour has ",
                                  current.numberOfNodes(), " nodes but the bending reference has ", nodes_);
  core::require<core::InputError>(current.closure() == closure_,
                                  "the deformed contour and the bending reference must be both periodic or both "
                                  "tethered");
  const std::vector<double>& l = current.knotArcLengths();
  const std::vector<double> kappa = knotCurvatures(current);
  std::vector<double> misfit = kappa;
  for (std::size_t i = 0; i < referenceCurvature_.size(); ++i) {
    misfit[i] -= referenceCurvature_[i];
  }
  std::optional<CubicSpline> referenceSpline;
  if (!referenceCurvature_.empty()) {
    referenceSpline.emplace(arcLengthSpline(l, referenceCurvature_, closure_));
  }
  BendingState2D state(law_.modulus, arcLengthSpline(l, misfit, closure_), std::move(referenceSpline));

  const int n = nodes_;
  state.curvature_.resize(n);
  state.misfit_.resize(n);
  state.load_.resize(2, n);
  for (int i = 0; i < n; ++i) {
    state.curvature_(i) = kappa[static_cast<std::size_t>(i)];
    state.misfit_(i) = misfit[static_cast<std::size_t>(i)];
    state.load_.col(i) = state.loadAt(current.nodePoint(i), i, 0.0);
  }

  // (k_b / 2) int q^2 dl: q is cubic in l on each piece, so 4 Gauss points are exact.
  const quadrature::Rule1D rule = quadrature::gaussLegendre(4);
  double energy = 0.0;
  for (int k = 0; k < n; ++k) {
    const double span = l[static_cast<std::size_t>(k) + 1] - l[static_cast<std::size_t>(k)];
    const contour::CubicPiece& q = state.misfitSpline_.piece(k);
    for (std::size_t p = 0; p < rule.points.size(); ++p) {
      const double value = q.value(rule.points[p] * span);
      energy += rule.weights[p] * span * value * value;
    }
  }
  state.energy_ = 0.5 * law_.modulus * energy;
  return state;
}

} // namespace capsula::scene2d
