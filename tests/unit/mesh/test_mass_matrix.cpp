// The consistent mass matrix of the quadratic surface (mesh::SurfaceMassMatrix): its
// total is the area, it is symmetric, and the solve inverts it.
#include <capsula/mesh/Measures.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/mesh/SurfaceMassMatrix.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace {

using capsula::mesh::SurfaceMassMatrix;
using capsula::mesh::SurfaceMesh;
using capsula::mesh::Vec3;

SurfaceMesh testSurface()
{
  return capsula::mesh::makeEllipsoid(2, Vec3(1.0, 0.6, 1.3));
}

} // namespace

TEST(SurfaceMassMatrix, RowSumsAddUpToTheArea)
{
  const SurfaceMesh mesh = testSurface();
  SurfaceMassMatrix M(mesh);
  M.assemble(mesh.positionData());
  const std::vector<double> nodal = M.nodalAreas();
  const double total = std::accumulate(nodal.begin(), nodal.end(), 0.0);
  // sum_k phi_k = 1, so sum_kl M_kl = int dS with the same 7-point rule: round-off.
  EXPECT_NEAR(total, capsula::mesh::surfaceArea(mesh, 7), 1e-12 * total);
  // M 1 (component by component) equals the nodal areas.
  std::vector<double> ones(3 * static_cast<std::size_t>(mesh.numNodes()), 1.0), y(ones.size());
  M.apply(ones.data(), y.data());
  for (int k = 0; k < mesh.numNodes(); ++k) {
    EXPECT_NEAR(y[3 * k + 1], nodal[k], 1e-14);
  }
}

TEST(SurfaceMassMatrix, IsSymmetric)
{
  const SurfaceMesh mesh = testSurface();
  SurfaceMassMatrix M(mesh);
  M.assemble(mesh.positionData());
  const std::size_t n = 3 * static_cast<std::size_t>(mesh.numNodes());
  std::vector<double> a(n), b(n), Ma(n), Mb(n);
  for (std::size_t i = 0; i < n; ++i) {
    a[i] = std::sin(1.3 * i);
    b[i] = std::cos(0.7 * i + 0.2);
  }
  M.apply(a.data(), Ma.data());
  M.apply(b.data(), Mb.data());
  const double bMa = std::inner_product(b.begin(), b.end(), Ma.begin(), 0.0);
  const double aMb = std::inner_product(a.begin(), a.end(), Mb.begin(), 0.0);
  EXPECT_NEAR(bMa, aMb, 1e-13 * std::abs(bMa));
}

TEST(SurfaceMassMatrix, SolveInvertsApply)
{
  const SurfaceMesh mesh = testSurface();
  SurfaceMassMatrix M(mesh);
  M.assemble(mesh.positionData());
  const std::size_t n = 3 * static_cast<std::size_t>(mesh.numNodes());
  // A rough field (no smoothness to help): f_i = sin(1.3 i).
  std::vector<double> f(n), F(n), solved(n);
  for (std::size_t i = 0; i < n; ++i) {
    f[i] = std::sin(1.3 * static_cast<double>(i)) + 0.5;
  }
  M.apply(f.data(), F.data());
  const int iterations = M.solve(F.data(), solved.data(), 1e-13);
  double worst = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    worst = std::max(worst, std::abs(solved[i] - f[i]));
  }
  // Residual 1e-13 relative in the max norm; cond(M) ~ 30 bounds the error near 1e-11.
  EXPECT_LT(worst, 1e-10);
  // Jacobi-preconditioned CG on a well-conditioned matrix: tens of iterations, not hundreds.
  EXPECT_LT(iterations, 100);
}
