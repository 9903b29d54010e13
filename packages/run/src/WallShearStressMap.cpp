#include "capsula/run/WallShearStressMap.hpp"

#include <capsula/core/Error.hpp>

#include <algorithm>
#include <cmath>

namespace capsula::run {

namespace core = capsula::core;

std::vector<mesh::Vec3> WallGrid::nodes() const
{
  std::vector<mesh::Vec3> points;
  points.reserve(static_cast<std::size_t>(numNodes()));
  for (int j = 0; j < nz; ++j) {
    for (int i = 0; i < nx; ++i) {
      points.push_back(node(i, j));
    }
  }
  return points;
}

WallGrid WallGrid::around(const domain::Wall& wall, double cx, double cz, double upstream, double downstream,
                          double halfWidth, double spacing)
{
  core::require<core::InputError>(spacing > 0.0 && upstream >= 0.0 && downstream >= 0.0 && halfWidth >= 0.0,
                                  "wall grid: the spacing must be > 0 and the extents >= 0.");
  const int up = static_cast<int>(std::ceil(upstream / spacing - 1e-9));
  const int down = static_cast<int>(std::ceil(downstream / spacing - 1e-9));
  const int side = static_cast<int>(std::ceil(halfWidth / spacing - 1e-9));
  WallGrid grid;
  grid.wall = wall;
  grid.spacing = spacing;
  grid.xMin = cx - up * spacing;
  grid.zMin = cz - side * spacing;
  grid.nx = up + down + 1;
  grid.nz = 2 * side + 1;
  return grid;
}

operators::WallShearStress wallShearStressOnGrid(operators::BoundaryIntegralSolver& solver, const WallGrid& grid,
                                                 double step, const operators::LoadDensity& load,
                                                 const double* nodeVelocities, const operators::FlowConditions& flow)
{
  core::require<core::InputError>(step > 0.0 && std::isfinite(step), "wall shear stress: the stencil step is ", step,
                                  "; it must be > 0.");
  constexpr int levels = 4;
  constexpr double wallWeight = -25.0;                          // on u_w
  constexpr double weights[levels] = {48.0, -36.0, 16.0, -3.0}; // / (12 h)
  const domain::Wall& wall = grid.wall;
  const std::vector<mesh::Vec3> nodes = grid.nodes();
  std::vector<double> points;
  points.reserve(3 * levels * nodes.size());
  for (const auto& p : nodes) {
    for (int level = 1; level <= levels; ++level) {
      points.insert(points.end(), {p[0], wall.height + wall.fluidSide * (level * step), p[2]});
    }
  }
  const std::vector<double> u = solver.flowVelocity(points, load, nodeVelocities, flow);
  operators::WallShearStress stress;
  stress.dudy.resize(nodes.size());
  stress.dwdy.resize(nodes.size());
  stress.magnitude.resize(nodes.size());
  for (std::size_t p = 0; p < nodes.size(); ++p) {
    // The disturbance vanishes on every wall (the kernels' no-slip condition), so the wall
    // moves with the undisturbed flow there: exactly 0 on the lower wall, where the term
    // leaves the sum unchanged.
    const mesh::Vec3 wallVelocity = flow.background.at(nodes[p]);
    double dudy = wallWeight * wallVelocity[0], dwdy = wallWeight * wallVelocity[2];
    for (int level = 0; level < levels; ++level) {
      const std::size_t k = 3 * (levels * p + static_cast<std::size_t>(level));
      dudy += weights[level] * u[k];
      dwdy += weights[level] * u[k + 2];
    }
    stress.dudy[p] = dudy / (12.0 * step);
    stress.dwdy[p] = dwdy / (12.0 * step);
    stress.magnitude[p] = std::hypot(stress.dudy[p], stress.dwdy[p]);
  }
  return stress;
}

ElevatedStressAreas elevatedStressAreas(const WallGrid& grid, const std::vector<double>& stress, double xCell,
                                        double threshold)
{
  core::require(static_cast<int>(stress.size()) == grid.numNodes(), "elevatedStressAreas: ", stress.size(),
                " values for ", grid.numNodes(), " grid nodes");
  ElevatedStressAreas areas;
  if (stress.empty()) {
    return areas;
  }
  areas.minimum = *std::min_element(stress.begin(), stress.end());
  areas.maximum = *std::max_element(stress.begin(), stress.end());
  const double h2 = grid.spacing * grid.spacing;
  const auto edgeWeight = [](int k, int n) { return (n > 1 && (k == 0 || k == n - 1)) ? 0.5 : 1.0; };
  for (int j = 0; j < grid.nz; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      if (stress[static_cast<std::size_t>(grid.index(i, j))] < threshold) {
        continue;
      }
      const double area = h2 * edgeWeight(i, grid.nx) * edgeWeight(j, grid.nz);
      const double x = grid.node(i, j)[0];
      if (std::abs(x - xCell) <= 1e-12 * std::max(1.0, std::abs(xCell))) {
        areas.upstream += 0.5 * area;
        areas.downstream += 0.5 * area;
      } else if (x < xCell) {
        areas.upstream += area;
      } else {
        areas.downstream += area;
      }
    }
  }
  return areas;
}

OutsideRangeAreas areasOutsideRange(const WallGrid& grid, const std::vector<double>& stress, double lowest,
                                    double highest)
{
  core::require(static_cast<int>(stress.size()) == grid.numNodes(), "areasOutsideRange: ", stress.size(),
                " values for ", grid.numNodes(), " grid nodes");
  OutsideRangeAreas areas;
  const double h2 = grid.spacing * grid.spacing;
  // The trapezoidal rule's node areas, as in elevatedStressAreas.
  const auto edgeWeight = [](int k, int n) { return (n > 1 && (k == 0 || k == n - 1)) ? 0.5 : 1.0; };
  for (int j = 0; j < grid.nz; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      const double sigma = stress[static_cast<std::size_t>(grid.index(i, j))];
      const double area = h2 * edgeWeight(i, grid.nx) * edgeWeight(j, grid.nz);
      if (sigma < lowest) {
        areas.below += area;
      } else if (sigma > highest) {
        areas.above += area;
      }
    }
  }
  return areas;
}

} // namespace capsula::run
