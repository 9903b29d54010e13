#pragma once
// Helpers shared by the operator tests: solvers on one rank, element-averaged loads from
// a field on the surface, and a report of the observed order of convergence under
// refinement (capsula/testing/ConvergenceOrder.hpp).
#include "capsula/testing/ConvergenceOrder.hpp"

#include <capsula/mesh/ElementGeometry.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/operators/KernelRegistry.hpp>
#include <capsula/quadrature/TriangleRule.hpp>

#include <Teuchos_DefaultSerialComm.hpp>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace capsula::operators::testing {

inline Teuchos::RCP<const Teuchos::Comm<int>> serialComm()
{
  return Teuchos::rcp(new Teuchos::SerialComm<int>);
}

inline std::unique_ptr<BoundaryIntegralSolver>
makeSolver(const std::string& kernel, std::vector<mesh::SurfaceMesh> cells, std::vector<double> lambdas,
           const DiscretisationParameters& discretisation = {}, const SolverParameters& solver = {})
{
  return builtInKernels().create(kernel, serialComm(), CellSurfaces(std::move(cells), std::move(lambdas)),
                                 discretisation, solver);
}

inline std::unique_ptr<BoundaryIntegralSolver> makeSolver(const std::string& kernel, mesh::SurfaceMesh cell,
                                                          double lambda = 1.0,
                                                          const DiscretisationParameters& discretisation = {},
                                                          const SolverParameters& solver = {})
{
  std::vector<mesh::SurfaceMesh> cells;
  cells.push_back(std::move(cell));
  return makeSolver(kernel, std::move(cells), {lambda}, discretisation, solver);
}

/// <f>_m = (1 / A_m) int_Em f(x, n) dS for every element of every cell (13-point rule),
/// f(position, outward normal) -> Vec3.
template <class Field>
std::vector<double> elementAverages(const CellSurfaces& surfaces, Field&& f)
{
  const auto& rule = quadrature::triangleRule(13);
  std::vector<double> loads;
  for (int c = 0; c < surfaces.numCells(); ++c) {
    const auto& cell = surfaces.cell(c);
    for (int e = 0; e < cell.numElements(); ++e) {
      const mesh::ElementNodes x = cell.elementNodes(e);
      const mesh::ShapeParameters p = mesh::shapeParameters(x);
      const double area = mesh::integrateOverElement(
          x, p, rule, [](const mesh::SurfacePoint&) { return 1.0; }, 0.0);
      const mesh::Vec3 integral = mesh::integrateOverElement(
          x, p, rule, [&](const mesh::SurfacePoint& s) { return mesh::Vec3(f(s.position, s.normal)); },
          mesh::Vec3(mesh::Vec3::Zero()));
      for (int i = 0; i < 3; ++i) {
        loads.push_back(integral[i] / area);
      }
    }
  }
  return loads;
}

/// Nodal values (3 per node) in the 18-per-element layout of LoadDensity: a continuous
/// load interpolated by the shape functions.
inline std::vector<double> gatherElementNodeValues(const CellSurfaces& surfaces, const std::vector<double>& nodal)
{
  std::vector<double> values;
  for (int c = 0; c < surfaces.numCells(); ++c) {
    const auto& cell = surfaces.cell(c);
    for (int e = 0; e < cell.numElements(); ++e) {
      for (const int node : cell.element(e)) {
        const std::size_t g = 3 * static_cast<std::size_t>(surfaces.nodeOffset(c) + node);
        values.insert(values.end(), {nodal[g], nodal[g + 1], nodal[g + 2]});
      }
    }
  }
  return values;
}

/// A nodal field g(position) at every node of every cell, 3 per node.
template <class Field>
std::vector<double> nodalField(const CellSurfaces& surfaces, Field&& g)
{
  std::vector<double> values;
  const std::vector<double> x = surfaces.positions();
  for (int n = 0; n < surfaces.numNodes(); ++n) {
    const mesh::Vec3 v = g(mesh::nodeAt(x.data(), n));
    values.insert(values.end(), {v[0], v[1], v[2]});
  }
  return values;
}

/// Prints "label: level l error e ..." and the fitted order; returns the order.
inline double reportConvergence(const std::string& label, const std::vector<int>& levels,
                                const std::vector<double>& errors)
{
  std::printf("%-52s", label.c_str());
  for (std::size_t i = 0; i < levels.size(); ++i) {
    std::printf("  n=%d %.3e", levels[i], errors[i]);
  }
  const double order = capsula::testing::orderOverLevels(levels, errors);
  std::printf("  order %.2f\n", order);
  return order;
}

} // namespace capsula::operators::testing
