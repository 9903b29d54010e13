#include "capsula/scene2d/PointSingleLayer2D.hpp"

#include <capsula/greens/FreeSpace2D.hpp>
#include <capsula/greens/Wall2D.hpp>
#include <capsula/quadrature/GaussLegendre.hpp>

#include <cmath>
#include <vector>

namespace capsula::scene2d {

namespace {

// int_0^a -ln s ds = a (1 - ln a).
double integratedMinusLog(double a)
{
  return a * (1.0 - std::log(a));
}

} // namespace

Eigen::MatrixXd pointSingleLayer2D(const contour::Contour& contour, bool wall)
{
  const int n = contour.numberOfNodes();
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  const auto stokeslet = [wall](const double* x, const double* x0, double G[2][2]) {
    if (wall) {
      greens::stokesletWall2D(x, x0, G);
    } else {
      const double xh[2] = {x[0] - x0[0], x[1] - x0[1]};
      greens::stokesletFreeSpace2D(xh, G);
    }
  };
  std::vector<double> share(static_cast<std::size_t>(n));
  for (int s = 0; s < n; ++s) {
    share[static_cast<std::size_t>(s)] = 0.5 * (contour.segmentLength((s + n - 1) % n) + contour.segmentLength(s));
  }
  // The images' part of a node's own share: 4 Gauss-Legendre points on either side (the
  // images lie at least twice the node's height away; a preconditioner needs no more).
  const quadrature::Rule1D rule = quadrature::gaussLegendre(4);
  for (int t = 0; t < n; ++t) {
    const double x0[2] = {contour.nodes()(0, t), contour.nodes()(1, t)};
    for (int s = 0; s < n; ++s) {
      if (s == t) {
        continue;
      }
      const double x[2] = {contour.nodes()(0, s), contour.nodes()(1, s)};
      double G[2][2];
      stokeslet(x, x0, G);
      const double w = share[static_cast<std::size_t>(s)];
      for (int i = 0; i < 2; ++i) {
        for (int j = 0; j < 2; ++j) {
          M(2 * t + j, 2 * s + i) = w * G[i][j];
        }
      }
    }
    // Its own share, straight along the tangent from -a to b.
    const double a = 0.5 * contour.segmentLength((t + n - 1) % n);
    const double b = 0.5 * contour.segmentLength(t);
    const Eigen::Vector2d tangent = contour.nodePoint(t).tangent;
    const double logPart = integratedMinusLog(a) + integratedMinusLog(b);
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) {
        M(2 * t + j, 2 * t + i) = (i == j ? logPart : 0.0) + (a + b) * tangent(i) * tangent(j);
      }
    }
    if (!wall) {
      continue;
    }
    for (const double side : {-a, b}) {
      for (std::size_t q = 0; q < rule.points.size(); ++q) {
        const double s = side * rule.points[q];
        const double x[2] = {x0[0] + s * tangent.x(), x0[1] + s * tangent.y()};
        const double xh[2] = {x[0] - x0[0], x[1] - x0[1]};
        double G[2][2], free[2][2];
        greens::stokesletWall2D(x, x0, G);
        greens::stokesletFreeSpace2D(xh, free);
        for (int i = 0; i < 2; ++i) {
          for (int j = 0; j < 2; ++j) {
            M(2 * t + j, 2 * t + i) += std::abs(side) * rule.weights[q] * (G[i][j] - free[i][j]);
          }
        }
      }
    }
  }
  return M;
}

} // namespace capsula::scene2d
