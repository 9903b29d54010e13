#pragma once
// Quadrature for the elements that hold the target node (thesis Section 3.6.2).
//
// In the parametric plane of the element the target sits at a vertex or at a midside
// node. Polar coordinates centred on it (eq 3.41) turn the 1/r singularity of G and of
// T . n into a bounded integrand: dxi deta = r' dr' dtheta. The parametric triangle is
// cut into sub-triangles (P, A, B) with the target P as apex, one for a vertex (eq 3.42)
// and two for a midside node (eq 3.43, split along the line to the opposite vertex); on
// each, Gauss-Legendre runs over r' from 0 to the opposite side AB and over the
// direction. The direction is not sampled in theta itself but in
//   u = asinh(tan(theta - theta_perp)),  theta_perp the direction of the perpendicular to AB,
// i.e. by the point Q = F + p sinh(u) e on the line AB (F the foot of the perpendicular,
// p its length). The reach R(theta) = p / cos(theta - theta_perp) of eqs 3.42-3.43 then
// becomes p cosh(u), smooth, and a 1/r integrand becomes constant in u: Gauss-Legendre in
// theta converges slowly on the wide sub-triangles of a midside node (the reach's poles
// at theta - theta_perp = +-pi/2 lie close to the interval), in u it does not.
#include <capsula/mesh/ShapeFunctions.hpp>
#include <capsula/quadrature/Rule1D.hpp>

#include <array>
#include <vector>

namespace capsula::operators {

/// A rule over (part of) the parametric triangle: int f dxi deta ~ sum_k w_k f(xi_k, eta_k).
struct ParametricRule {
  std::vector<double> xi, eta, weight;

  int size() const { return static_cast<int>(weight.size()); }
  /// Empties the rule and keeps its storage.
  void clear()
  {
    xi.clear();
    eta.clear();
    weight.clear();
  }
};

using ParametricPoint = std::array<double, 2>;

/// Appends the polar rule over the parametric triangle (apex, a, b) centred on the apex,
/// with `gauss` (a rule on [0, 1]) mapped onto u in [u_a, u_b] and onto s = r' / R in [0, 1];
/// weight = w_u (u_b - u_a) p^2 cosh(u) w_s s.
void appendPolarRule(const ParametricPoint& apex, const ParametricPoint& a, const ParametricPoint& b,
                     const quadrature::Rule1D& gauss, ParametricRule& rule);

/// The polar rule of the whole parametric triangle around local node `localNode` (0..5)
/// of an element with midside positions `shape`: one sub-triangle for a vertex, two for
/// a midside node. `gauss` is the N_GL-point Gauss-Legendre rule on [0, 1]. Replaces
/// the contents of `rule` (no allocation once its storage has grown).
void singularRule(int localNode, const mesh::ShapeParameters& shape, const quadrature::Rule1D& gauss,
                  ParametricRule& rule);

} // namespace capsula::operators
