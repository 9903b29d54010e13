#pragma once
// Reference values for the bending tests: the exact bending load of an ellipsoid and its
// virtual work on smooth test displacements, against which the discrete nodal forces of
// HelfrichBending are measured.
#include <capsula/mesh/EllipsoidCurvature.hpp>
#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/quadrature/GaussLegendre.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

namespace capsula::elasticity::testing {

using mesh::Vec3;

constexpr double pi = 3.14159265358979323846;

// Lap_s H of the ellipsoid at a surface point: H extended off the surface by the closed
// form of EllipsoidCurvature.hpp (smooth in space), then Lap_s F = tr(P grad grad F) -
// 2H n . grad F (div_s P = -2H n), the derivatives by fourth-order central differences
// (step 2e-3: truncation ~1e-11, round-off ~1e-10 of the curvature scale).
inline double ellipsoidLaplacianOfH(const Vec3& axes, const Vec3& x)
{
  const auto F = [&](const Vec3& y) { return mesh::ellipsoidCurvature(axes, y).mean; };
  const double h = 2e-3;
  const double w[4] = {1.0, -8.0, 8.0, -1.0}; // at -2h, -h, h, 2h, over 12 h
  const double s[4] = {-2.0, -1.0, 1.0, 2.0};
  Vec3 gradient;
  double hessian[3][3];
  for (int i = 0; i < 3; ++i) {
    const Vec3 ei = Vec3::Unit(i);
    gradient[i] = 0.0;
    for (int a = 0; a < 4; ++a) {
      gradient[i] += w[a] * F(x + s[a] * h * ei) / (12.0 * h);
    }
    hessian[i][i] =
        (-F(x + 2 * h * ei) + 16 * F(x + h * ei) - 30 * F(x) + 16 * F(x - h * ei) - F(x - 2 * h * ei)) / (12.0 * h * h);
    for (int j = 0; j < i; ++j) {
      const Vec3 ej = Vec3::Unit(j);
      double sum = 0.0;
      for (int a = 0; a < 4; ++a) {
        for (int b = 0; b < 4; ++b) {
          sum += w[a] * w[b] * F(x + s[a] * h * ei + s[b] * h * ej);
        }
      }
      hessian[i][j] = hessian[j][i] = sum / (144.0 * h * h);
    }
  }
  const Vec3 n = mesh::ellipsoidNormal(axes, x);
  double laplacian = 0.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      laplacian += ((i == j ? 1.0 : 0.0) - n[i] * n[j]) * hessian[i][j];
    }
  }
  return laplacian - 2.0 * F(x) * n.dot(gradient);
}

// The analytic bending load density Delta f . n = -k_b [2 Lap_s H + (2H - c0)(2H^2 - 2K + c0 H)]
// on the ellipsoid (the first variation of the energy under a normal displacement).
inline double ellipsoidBendingLoad(double kb, const Vec3& axes, double c0, const Vec3& x)
{
  const auto c = mesh::ellipsoidCurvature(axes, x);
  const double H = c.mean, K = c.gaussian;
  return -kb * (2.0 * ellipsoidLaplacianOfH(axes, x) + (2.0 * H - c0) * (2.0 * H * H - 2.0 * K + c0 * H));
}

// Smooth test displacements psi for the weak (virtual-work) form of the load.
using TestField = std::function<Vec3(const Vec3&)>;
inline std::vector<TestField> testFields(const Vec3& axes)
{
  return {
      [axes](const Vec3& x) { return mesh::ellipsoidNormal(axes, x); },
      [](const Vec3& x) { return Vec3(std::sin(x[0] + 0.3), std::cos(1.1 * x[1]) * x[2], x[0] * x[1] * x[2] + x[2]); },
      [](const Vec3& x) { return Vec3(std::exp(0.5 * x[0]) * Vec3(0.2, x[1], x[2] * x[2])); }};
}

// int_S g dA over the exact ellipsoid, by Gauss-Legendre in the polar angle and the
// (spectrally accurate) trapezoidal rule in the azimuth: ~1e-10 relative for these g.
template <typename Integrand>
double ellipsoidIntegral(const Vec3& axes, Integrand&& g)
{
  const quadrature::Rule1D theta = quadrature::gaussLegendre(40, 0.0, pi);
  const int numPhi = 80;
  double sum = 0.0;
  for (std::size_t i = 0; i < theta.points.size(); ++i) {
    const double t = theta.points[i], st = std::sin(t), ct = std::cos(t);
    for (int j = 0; j < numPhi; ++j) {
      const double p = 2.0 * pi * j / numPhi, sp = std::sin(p), cp = std::cos(p);
      const Vec3 x(axes[0] * st * cp, axes[1] * st * sp, axes[2] * ct);
      const Vec3 xt(axes[0] * ct * cp, axes[1] * ct * sp, -axes[2] * st);
      const Vec3 xp(-axes[0] * st * sp, axes[1] * st * cp, 0.0);
      sum += g(x) * xt.cross(xp).norm() * theta.weights[i] * (2.0 * pi / numPhi);
    }
  }
  return sum;
}

// The largest over the test fields of |sum_k F_k . psi(x_k) - int (Delta f . n)(psi . n) dA|
// (the virtual work of psi, discrete against exact), relative to `scale` (a load) times
// int |psi| dA.
inline double virtualWorkError(const mesh::SurfaceMesh& mesh, const std::vector<Vec3>& F, double kb, const Vec3& axes,
                               double c0, double scale)
{
  double worst = 0.0;
  for (const TestField& psi : testFields(axes)) {
    double discrete = 0.0;
    for (int k = 0; k < mesh.numNodes(); ++k) {
      discrete += F[static_cast<std::size_t>(k)].dot(psi(mesh.position(k)));
    }
    const double exact = ellipsoidIntegral(axes, [&](const Vec3& x) {
      return ellipsoidBendingLoad(kb, axes, c0, x) * psi(x).dot(mesh::ellipsoidNormal(axes, x));
    });
    const double size = ellipsoidIntegral(axes, [&](const Vec3& x) { return psi(x).norm(); });
    worst = std::max(worst, std::abs(discrete - exact) / (scale * size));
  }
  return worst;
}

} // namespace capsula::elasticity::testing
