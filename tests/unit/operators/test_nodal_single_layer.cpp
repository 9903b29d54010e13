// The single layer of a load given at the nodes with cached correction blocks
// (BoundaryIntegralSolver::singleLayerOfNodalLoad) against the plain single layer of the
// same load: identical rules, so round-off where no element is near-singular, the
// near-singular tolerance where the adaptive subdivision sees another integrand; and the
// cache follows the geometry.
#include "OperatorTesting.hpp"

#include <capsula/mesh/Shapes.hpp>
#include <capsula/operators/LoadDensity.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

namespace mesh = capsula::mesh;
namespace op = capsula::operators;
namespace ot = capsula::operators::testing;
using mesh::Vec3;

// A smooth load and its element-node layout (LoadDensity.hpp).
std::vector<double> nodalLoad(const mesh::SurfaceMesh& cell)
{
  std::vector<double> f(3 * static_cast<std::size_t>(cell.numNodes()));
  for (int i = 0; i < cell.numNodes(); ++i) {
    const Vec3 x = mesh::nodeAt(cell.positions().data(), i);
    f[3 * i] = std::sin(2.0 * x[1]) + 0.3;
    f[3 * i + 1] = x[0] * x[2];
    f[3 * i + 2] = std::cos(x[0] + x[1]);
  }
  return f;
}

std::vector<double> elementNodeLayout(const mesh::SurfaceMesh& cell, const std::vector<double>& f)
{
  std::vector<double> values;
  for (int e = 0; e < cell.numElements(); ++e) {
    for (const int node : cell.element(e)) {
      values.insert(values.end(), {f[3 * node], f[3 * node + 1], f[3 * node + 2]});
    }
  }
  return values;
}

double relativeDifference(const std::vector<double>& a, const std::vector<double>& b)
{
  double d = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    d = std::max(d, std::abs(a[i] - b[i]));
    scale = std::max(scale, std::abs(b[i]));
  }
  return d / scale;
}

} // namespace

TEST(NodalSingleLayer, AgreesWithTheSingleLayerOfTheSameLoad)
{
  // Free space, no near-singular elements: the same rules in another order (1e-13).
  {
    const mesh::SurfaceMesh cell = mesh::makeSphere(2, 1.0);
    op::DiscretisationParameters d;
    d.nearSingularDistance = 0.0;
    auto solver = ot::makeSolver("FreeSpace", cell, 1.0, d);
    const auto f = nodalLoad(cell);
    const auto layout = elementNodeLayout(cell, f);
    EXPECT_LT(relativeDifference(solver->singleLayerOfNodalLoad(f.data()),
                                 solver->singleLayer(op::LoadDensity(layout.data()))),
              1e-13);
  }
  // Near the wall: the nodes' images are near-singular, integrated adaptively to 1e-6
  // of each element's contribution for either integrand.
  {
    const mesh::SurfaceMesh cell = mesh::makeSphere(2, 1.0, {Vec3(0.0, 1.1, 0.0), mesh::Mat3::Identity()});
    auto solver = ot::makeSolver("Wall", cell);
    const auto f = nodalLoad(cell);
    const auto layout = elementNodeLayout(cell, f);
    EXPECT_LT(relativeDifference(solver->singleLayerOfNodalLoad(f.data()),
                                 solver->singleLayer(op::LoadDensity(layout.data()))),
              1e-6);
  }
}

// The cached corrections belong to one geometry: after setPositions the next call uses
// the new one (a stale cache would give the old sphere's single layer).
TEST(NodalSingleLayer, CacheFollowsTheGeometry)
{
  mesh::SurfaceMesh cell = mesh::makeSphere(1, 1.0);
  op::DiscretisationParameters d;
  d.nearSingularDistance = 0.0;
  auto solver = ot::makeSolver("FreeSpace", cell, 1.0, d);
  const auto f = nodalLoad(cell);
  solver->singleLayerOfNodalLoad(f.data());
  std::vector<double> moved = cell.positions();
  for (std::size_t i = 0; i < moved.size(); i += 3) {
    moved[i] *= 1.3; // a spheroid
  }
  solver->setPositions(moved.data());
  cell.setPositions(moved.data());
  const auto layout = elementNodeLayout(cell, f);
  EXPECT_LT(
      relativeDifference(solver->singleLayerOfNodalLoad(f.data()), solver->singleLayer(op::LoadDensity(layout.data()))),
      1e-13);
}
