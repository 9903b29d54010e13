#pragma once
// Geometry of one quadratic triangle: the map (xi, eta) -> x of eqs 3.20-3.24.
//
// Everything works on the element's six node positions gathered into an
// ElementNodes array, so the same code evaluates the current configuration, a
// reference configuration, or a trial (Runge-Kutta stage) configuration: gather
// from whichever flat position array you hold. The ShapeParameters are passed
// separately so a caller can keep the parametrisation of one configuration (e.g.
// the reference alpha, beta, gamma, which keeps (xi, eta) material) while
// evaluating another.
#include <capsula/mesh/ShapeFunctions.hpp>
#include <capsula/mesh/Vec3.hpp>

#include <array>
#include <cstddef>

namespace capsula::mesh {

/// Positions of the six nodes of one element, in the thesis's node order.
using ElementNodes = std::array<Vec3, 6>;

/// Copies the six nodes listed in `connectivity` out of a flat position array.
inline ElementNodes gatherElementNodes(const std::array<int, 6>& connectivity, const double* positions)
{
  ElementNodes x;
  for (int i = 0; i < 6; ++i) {
    x[i] = nodeAt(positions, connectivity[i]);
  }
  return x;
}

/// The surface at one parametric point of an element.
struct SurfacePoint {
  Vec3 position;   ///< x(xi, eta), eq 3.20
  Vec3 tangentXi;  ///< dx/dxi, eq 3.21
  Vec3 tangentEta; ///< dx/deta, eq 3.22
  Vec3 normal;     ///< (x_xi cross x_eta) / h_s, eq 3.23; outward on an outward-oriented mesh
  double metric;   ///< h_s = |x_xi cross x_eta|, eq 3.24: dS = h_s dxi deta
};

/// x(xi, eta) only (eq 3.20).
inline Vec3 surfacePosition(const ElementNodes& x, const ShapeParameters& p, double xi, double eta)
{
  double phi[6];
  shapeFunctions(p, xi, eta, phi);
  Vec3 position = Vec3::Zero();
  for (int i = 0; i < 6; ++i) {
    position += phi[i] * x[i];
  }
  return position;
}

/// Position, tangents, unit normal and metric at (xi, eta) (eqs 3.20-3.24).
inline SurfacePoint evaluateSurfacePoint(const ElementNodes& x, const ShapeParameters& p, double xi, double eta)
{
  double phi[6], dXi[6], dEta[6];
  shapeFunctions(p, xi, eta, phi);
  shapeFunctionDerivatives(p, xi, eta, dXi, dEta);
  SurfacePoint s;
  s.position = Vec3::Zero();
  s.tangentXi = Vec3::Zero();
  s.tangentEta = Vec3::Zero();
  for (int i = 0; i < 6; ++i) {
    const Vec3& xi_i = x[i];
    s.position += phi[i] * xi_i;
    s.tangentXi += dXi[i] * xi_i;
    s.tangentEta += dEta[i] * xi_i;
  }
  const Vec3 areaVector = s.tangentXi.cross(s.tangentEta);
  s.metric = areaVector.norm();
  s.normal = areaVector / s.metric;
  return s;
}

/// Surface point at local node i (0..5) of the element.
inline SurfacePoint evaluateAtNode(const ElementNodes& x, const ShapeParameters& p, int i)
{
  const auto c = nodeParametricCoordinates(p, i);
  return evaluateSurfacePoint(x, p, c[0], c[1]);
}

/// int_E f dS with a triangle rule over the reference triangle (weights summing to
/// 1/2, as capsula::quadrature::TriangleRule): sum_q w_q f(s_q) h_s(q) (eq 3.39).
/// f takes a SurfacePoint and returns anything that can be scaled and summed
/// (double, Vec3, Mat3); `zero` is the additive identity of that type.
template <typename Rule, typename Integrand, typename Value>
inline Value integrateOverElement(const ElementNodes& x, const ShapeParameters& p, const Rule& rule, Integrand&& f,
                                  Value zero)
{
  Value sum = zero;
  for (std::size_t q = 0; q < rule.weight.size(); ++q) {
    const SurfacePoint s = evaluateSurfacePoint(x, p, rule.xi[q], rule.eta[q]);
    sum += (rule.weight[q] * s.metric) * f(s);
  }
  return sum;
}

} // namespace capsula::mesh
