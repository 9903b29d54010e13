#include "capsula/mesh/SurfaceMassMatrix.hpp"

#include "capsula/mesh/ElementGeometry.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/quadrature/TriangleRule.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace capsula::mesh {

SurfaceMassMatrix::SurfaceMassMatrix(const SurfaceMesh& mesh)
    : mesh_(&mesh),
      element_(static_cast<std::size_t>(mesh.numElements())),
      diagonal_(static_cast<std::size_t>(mesh.numNodes()))
{
  const std::size_t n = 3 * static_cast<std::size_t>(mesh.numNodes());
  r_.resize(n);
  z_.resize(n);
  p_.resize(n);
  q_.resize(n);
}

void SurfaceMassMatrix::assemble(const double* positions)
{
  std::fill(diagonal_.begin(), diagonal_.end(), 0.0);
  for (int e = 0; e < mesh_->numElements(); ++e) {
    const ElementNodes x = mesh_->elementNodes(e, positions);
    assembleElement(e, x, shapeParameters(x));
  }
}

void SurfaceMassMatrix::assemble(const double* positions, const std::vector<ShapeParameters>& parameters)
{
  core::require(parameters.size() == static_cast<std::size_t>(mesh_->numElements()),
                "SurfaceMassMatrix: ", parameters.size(), " shape parameter sets for ", mesh_->numElements(),
                " elements");
  std::fill(diagonal_.begin(), diagonal_.end(), 0.0);
  for (int e = 0; e < mesh_->numElements(); ++e) {
    assembleElement(e, mesh_->elementNodes(e, positions), parameters[static_cast<std::size_t>(e)]);
  }
}

void SurfaceMassMatrix::assembleElement(int e, const ElementNodes& x, const ShapeParameters& p)
{
  const quadrature::TriangleRule& rule = quadrature::triangleRule(7);
  std::array<double, 36>& M = element_[static_cast<std::size_t>(e)];
  M.fill(0.0);
  for (int q = 0; q < rule.size(); ++q) {
    const SurfacePoint s = evaluateSurfacePoint(x, p, rule.xi[q], rule.eta[q]);
    double phi[6];
    shapeFunctions(p, rule.xi[q], rule.eta[q], phi);
    const double w = rule.weight[q] * s.metric;
    for (int k = 0; k < 6; ++k) {
      for (int l = 0; l < 6; ++l) {
        M[6 * k + l] += w * phi[k] * phi[l];
      }
    }
  }
  for (int k = 0; k < 6; ++k) {
    diagonal_[static_cast<std::size_t>(mesh_->element(e)[k])] += M[6 * k + k];
  }
}

void SurfaceMassMatrix::apply(const double* x, double* y) const
{
  std::fill(y, y + 3 * static_cast<std::size_t>(mesh_->numNodes()), 0.0);
  for (int e = 0; e < mesh_->numElements(); ++e) {
    const auto& nodes = mesh_->element(e);
    const std::array<double, 36>& M = element_[static_cast<std::size_t>(e)];
    for (int k = 0; k < 6; ++k) {
      double sum[3] = {0.0, 0.0, 0.0};
      for (int l = 0; l < 6; ++l) {
        const double* xl = x + 3 * static_cast<std::size_t>(nodes[l]);
        sum[0] += M[6 * k + l] * xl[0];
        sum[1] += M[6 * k + l] * xl[1];
        sum[2] += M[6 * k + l] * xl[2];
      }
      double* yk = y + 3 * static_cast<std::size_t>(nodes[k]);
      yk[0] += sum[0];
      yk[1] += sum[1];
      yk[2] += sum[2];
    }
  }
}

int SurfaceMassMatrix::solve(const double* F, double* f, double tolerance)
{
  // Preconditioned CG, the three components at once (each with its own step lengths).
  const std::size_t n = 3 * static_cast<std::size_t>(mesh_->numNodes());
  double rz[3] = {0.0, 0.0, 0.0}, target[3] = {0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < n; ++i) {
    const double d = diagonal_[i / 3];
    f[i] = F[i] / d;
  }
  apply(f, q_.data());
  for (std::size_t i = 0; i < n; ++i) {
    r_[i] = F[i] - q_[i];
    z_[i] = r_[i] / diagonal_[i / 3];
    p_[i] = z_[i];
    rz[i % 3] += r_[i] * z_[i];
    target[i % 3] = std::max(target[i % 3], tolerance * std::abs(F[i]));
  }
  for (int iteration = 0; iteration <= 500; ++iteration) {
    double residual[3] = {0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < n; ++i) {
      residual[i % 3] = std::max(residual[i % 3], std::abs(r_[i]));
    }
    if (residual[0] <= target[0] && residual[1] <= target[1] && residual[2] <= target[2]) {
      return iteration;
    }
    apply(p_.data(), q_.data());
    double pq[3] = {0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < n; ++i) {
      pq[i % 3] += p_[i] * q_[i];
    }
    double step[3];
    for (int d = 0; d < 3; ++d) {
      step[d] = pq[d] > 0.0 ? rz[d] / pq[d] : 0.0;
    }
    double rzNew[3] = {0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < n; ++i) {
      f[i] += step[i % 3] * p_[i];
      r_[i] -= step[i % 3] * q_[i];
      z_[i] = r_[i] / diagonal_[i / 3];
      rzNew[i % 3] += r_[i] * z_[i];
    }
    for (std::size_t i = 0; i < n; ++i) {
      const int d = static_cast<int>(i % 3);
      p_[i] = z_[i] + (rz[d] > 0.0 ? rzNew[d] / rz[d] : 0.0) * p_[i];
    }
    for (int d = 0; d < 3; ++d) {
      rz[d] = rzNew[d];
    }
  }
  throw core::NumericalError(
      core::message("the surface mass matrix solve did not converge in 500 conjugate-gradient iterations "
                    "(a degenerate or folded element?)"));
}

std::vector<double> SurfaceMassMatrix::nodalAreas() const
{
  std::vector<double> area(static_cast<std::size_t>(mesh_->numNodes()), 0.0);
  nodalAreas(area.data());
  return area;
}

void SurfaceMassMatrix::nodalAreas(double* area) const
{
  std::fill(area, area + mesh_->numNodes(), 0.0);
  for (int e = 0; e < mesh_->numElements(); ++e) {
    const std::array<double, 36>& M = element_[static_cast<std::size_t>(e)];
    for (int k = 0; k < 6; ++k) {
      double row = 0.0;
      for (int l = 0; l < 6; ++l) {
        row += M[6 * k + l];
      }
      area[mesh_->element(e)[k]] += row;
    }
  }
}

} // namespace capsula::mesh
