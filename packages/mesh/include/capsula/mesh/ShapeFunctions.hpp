#pragma once
// Shape functions of the 6-node quadratic triangle (thesis Section 3.3).
//
// Nodes 1..6 (indices 0..5 here) sit at the parametric points
//   (0,0), (1,0), (0,1), (alpha,0), (gamma,1-gamma), (0,beta):
// three vertices, then the midside nodes of edges 1-2, 2-3 and 3-1. alpha, beta and
// gamma place the midside nodes where their spacing along the element edges puts
// them (eq 3.17), so an unevenly placed midside node does not distort the map.
// All functions are allocation-free and inline so they can sit in inner loops.
#include <array>
#include <cmath>

namespace capsula::mesh {

/// Parametric positions of the three midside nodes (eq 3.17).
struct ShapeParameters {
  double alpha = 0.5; ///< node 4 at (alpha, 0) on edge 1-2
  double beta = 0.5;  ///< node 6 at (0, beta) on edge 3-1
  double gamma = 0.5; ///< node 5 at (gamma, 1 - gamma) on edge 2-3
};

/// Eq 3.17 from the six node positions (any type with operator- and .norm(),
/// e.g. Vec3). Each parameter is the fraction of the polygonal edge length
/// between the first vertex of the parametric axis and the midside node.
template <typename Point>
inline ShapeParameters shapeParameters(const std::array<Point, 6>& x)
{
  ShapeParameters p;
  p.alpha = 1.0 / (1.0 + (x[3] - x[1]).norm() / (x[3] - x[0]).norm());
  p.beta = 1.0 / (1.0 + (x[5] - x[2]).norm() / (x[5] - x[0]).norm());
  p.gamma = 1.0 / (1.0 + (x[4] - x[1]).norm() / (x[4] - x[2]).norm());
  return p;
}

/// Parametric coordinates (xi, eta) of local node i = 0..5.
inline std::array<double, 2> nodeParametricCoordinates(const ShapeParameters& p, int i)
{
  switch (i) {
  case 0:
    return {0.0, 0.0};
  case 1:
    return {1.0, 0.0};
  case 2:
    return {0.0, 1.0};
  case 3:
    return {p.alpha, 0.0};
  case 4:
    return {p.gamma, 1.0 - p.gamma};
  default:
    return {0.0, p.beta};
  }
}

/// phi_i(xi, eta), i = 0..5 (eq 3.19, ERRATA fix in phi_3: (beta + gamma - 1)/gamma).
inline void shapeFunctions(const ShapeParameters& p, double xi, double eta, double phi[6])
{
  const double a = p.alpha, b = p.beta, g = p.gamma;
  const double zeta = 1.0 - xi - eta;
  phi[1] = xi * (xi - a + (a - g) / (1.0 - g) * eta) / (1.0 - a);
  phi[2] = eta * (eta - b + (b + g - 1.0) / g * xi) / (1.0 - b);
  phi[3] = xi * zeta / (a * (1.0 - a));
  phi[4] = xi * eta / (g * (1.0 - g));
  phi[5] = eta * zeta / (b * (1.0 - b));
  phi[0] = 1.0 - phi[1] - phi[2] - phi[3] - phi[4] - phi[5];
}

/// d phi_i / d xi and d phi_i / d eta, i = 0..5 (derivatives of eq 3.19).
inline void shapeFunctionDerivatives(const ShapeParameters& p, double xi, double eta, double dXi[6], double dEta[6])
{
  const double a = p.alpha, b = p.beta, g = p.gamma;
  const double c2 = (a - g) / (1.0 - g); // coupling term of phi_2
  const double c3 = (b + g - 1.0) / g;   // coupling term of phi_3
  const double s4 = 1.0 / (a * (1.0 - a));
  const double s5 = 1.0 / (g * (1.0 - g));
  const double s6 = 1.0 / (b * (1.0 - b));
  dXi[1] = (2.0 * xi - a + c2 * eta) / (1.0 - a);
  dEta[1] = c2 * xi / (1.0 - a);
  dXi[2] = c3 * eta / (1.0 - b);
  dEta[2] = (2.0 * eta - b + c3 * xi) / (1.0 - b);
  dXi[3] = (1.0 - 2.0 * xi - eta) * s4;
  dEta[3] = -xi * s4;
  dXi[4] = eta * s5;
  dEta[4] = xi * s5;
  dXi[5] = -eta * s6;
  dEta[5] = (1.0 - xi - 2.0 * eta) * s6;
  dXi[0] = -(dXi[1] + dXi[2] + dXi[3] + dXi[4] + dXi[5]);
  dEta[0] = -(dEta[1] + dEta[2] + dEta[3] + dEta[4] + dEta[5]);
}

} // namespace capsula::mesh
