#pragma once
// Curvature of the quadratic element map x(xi, eta) (eqs 3.19-3.20) at one parametric
// point, from the first and second fundamental forms of the map.
//
// Sign convention (used by every curvature in capsula::mesh): with the unit normal n
// pointing OUT of the enclosed volume, the principal curvatures of a sphere of radius R
// are +1/R, so
//   mean curvature      kappa = (k1 + k2) / 2 = +1/R   (kappa = div_s n / 2),
//   Gaussian curvature  K     = k1 k2         = 1/R^2.
// This is the kappa of the Laplace law Delta f = 2 T kappa n for a uniform isotropic
// tension T (ERRATA, eq 3.7) and of the bending load eq 5.2.
// All functions are inline and allocation-free.
#include <capsula/mesh/ElementGeometry.hpp>
#include <capsula/mesh/ShapeFunctions.hpp>
#include <capsula/mesh/Vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace capsula::mesh {

/// Second derivatives of phi_i (eq 3.19, ERRATA fix in phi_3). phi_i is quadratic, so
/// they are constant over the element.
inline void shapeFunctionSecondDerivatives(const ShapeParameters& p, double dXiXi[6], double dXiEta[6],
                                           double dEtaEta[6])
{
  const double a = p.alpha, b = p.beta, g = p.gamma;
  const double s4 = 1.0 / (a * (1.0 - a));
  const double s5 = 1.0 / (g * (1.0 - g));
  const double s6 = 1.0 / (b * (1.0 - b));
  dXiXi[1] = 2.0 / (1.0 - a);
  dXiEta[1] = (a - g) / ((1.0 - g) * (1.0 - a));
  dEtaEta[1] = 0.0;
  dXiXi[2] = 0.0;
  dXiEta[2] = (b + g - 1.0) / (g * (1.0 - b));
  dEtaEta[2] = 2.0 / (1.0 - b);
  dXiXi[3] = -2.0 * s4;
  dXiEta[3] = -s4;
  dEtaEta[3] = 0.0;
  dXiXi[4] = 0.0;
  dXiEta[4] = s5;
  dEtaEta[4] = 0.0;
  dXiXi[5] = 0.0;
  dXiEta[5] = -s6;
  dEtaEta[5] = -2.0 * s6;
  dXiXi[0] = -(dXiXi[1] + dXiXi[2] + dXiXi[3] + dXiXi[4] + dXiXi[5]);
  dXiEta[0] = -(dXiEta[1] + dXiEta[2] + dXiEta[3] + dXiEta[4] + dXiEta[5]);
  dEtaEta[0] = -(dEtaEta[1] + dEtaEta[2] + dEtaEta[3] + dEtaEta[4] + dEtaEta[5]);
}

/// Mean and Gaussian curvature in the sign convention above.
struct CurvaturePair {
  double mean;
  double gaussian;
};

/// From the first fundamental form (E, F, G) = (x_u.x_u, x_u.x_v, x_v.x_v) and the second
/// (L, M, N) = (x_uu.n, x_uv.n, x_vv.n) of any parametrisation with n = outward unit normal:
/// the textbook H = (EN - 2FM + GL) / (2(EG - F^2)) is -1/R on an outward-normal sphere
/// (x_uu points inwards), so kappa = -H; K = (LN - M^2)/(EG - F^2) does not depend on the
/// sign of n.
inline CurvaturePair curvatureFromFundamentalForms(double E, double F, double G, double L, double M, double N)
{
  const double det = E * G - F * F;
  return {-(E * N - 2.0 * F * M + G * L) / (2.0 * det), (L * N - M * M) / det};
}

/// Curvature of the graph z = f(x, y) at a point where f has first derivatives (fx, fy)
/// and second derivatives (fxx, fxy, fyy), for the normal (-fx, -fy, 1)/w on the +z side
/// (the local fits put z along the outward normal).
inline CurvaturePair graphCurvature(double fx, double fy, double fxx, double fxy, double fyy)
{
  // The graph map (x, y) -> (x, y, f): E = 1 + fx^2, F = fx fy, G = 1 + fy^2 and
  // (L, M, N) = (fxx, fxy, fyy) / w with w = sqrt(1 + fx^2 + fy^2).
  const double w = std::sqrt(1.0 + fx * fx + fy * fy);
  return curvatureFromFundamentalForms(1.0 + fx * fx, fx * fy, 1.0 + fy * fy, fxx / w, fxy / w, fyy / w);
}

/// max(|k1|, |k2|) = |kappa| + sqrt(kappa^2 - K). The discriminant is a square for a
/// true surface; an estimated (kappa, K) can make it slightly negative, so it is
/// clipped at zero.
inline double maxAbsPrincipalCurvature(double mean, double gaussian)
{
  return std::abs(mean) + std::sqrt(std::max(mean * mean - gaussian, 0.0));
}

/// The element surface at one parametric point, with its curvature.
struct CurvedSurfacePoint {
  Vec3 normal;     ///< (x_xi cross x_eta) / h_s, eq 3.23
  double metric;   ///< h_s, eq 3.24
  double mean;     ///< kappa (sign convention above)
  double gaussian; ///< K
};

/// Normal, metric and curvature of the element map at (xi, eta).
inline CurvedSurfacePoint evaluateCurvature(const ElementNodes& x, const ShapeParameters& p, double xi, double eta)
{
  double dXi[6], dEta[6], dXiXi[6], dXiEta[6], dEtaEta[6];
  shapeFunctionDerivatives(p, xi, eta, dXi, dEta);
  shapeFunctionSecondDerivatives(p, dXiXi, dXiEta, dEtaEta);
  Vec3 xXi = Vec3::Zero(), xEta = Vec3::Zero();
  Vec3 xXiXi = Vec3::Zero(), xXiEta = Vec3::Zero(), xEtaEta = Vec3::Zero();
  for (std::size_t i = 0; i < 6; ++i) {
    xXi += dXi[i] * x[i];
    xEta += dEta[i] * x[i];
    xXiXi += dXiXi[i] * x[i];
    xXiEta += dXiEta[i] * x[i];
    xEtaEta += dEtaEta[i] * x[i];
  }
  const Vec3 areaVector = xXi.cross(xEta);
  CurvedSurfacePoint s;
  s.metric = areaVector.norm();
  s.normal = areaVector / s.metric;
  const CurvaturePair k = curvatureFromFundamentalForms(
      xXi.dot(xXi), xXi.dot(xEta), xEta.dot(xEta), xXiXi.dot(s.normal), xXiEta.dot(s.normal), xEtaEta.dot(s.normal));
  s.mean = k.mean;
  s.gaussian = k.gaussian;
  return s;
}

/// The same at local node i (0..5) of the element.
inline CurvedSurfacePoint evaluateCurvatureAtNode(const ElementNodes& x, const ShapeParameters& p, int i)
{
  const auto c = nodeParametricCoordinates(p, i);
  return evaluateCurvature(x, p, c[0], c[1]);
}

} // namespace capsula::mesh
