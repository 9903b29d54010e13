#include "capsula/run/PairMetrics.hpp"

#include <capsula/scene/CellStability.hpp>

#include <algorithm>
#include <cmath>

namespace capsula::run {

using scene::localElementSize;
using scene::minimumSurfaceGap;
using scene::SurfaceGap;

namespace {

// The gap between cell i and the nearest periodic image of cell j (SurfaceGap.hpp).
SurfaceGap gapBetween(const scene::Scene& scene, const std::vector<double>& positions, int i, int j)
{
  return scene::minimumSurfaceGap(scene.cell(i), positions.data() + 3 * static_cast<std::size_t>(scene.nodeOffset(i)),
                                  scene.cell(j), positions.data() + 3 * static_cast<std::size_t>(scene.nodeOffset(j)),
                                  scene.description().domain);
}

// The local element size of `cell` (at `x`) near `point`: that of its nearest node.
double elementSizeNear(const mesh::SurfaceMesh& cell, const mesh::Vec3& point)
{
  int nearest = 0;
  double best = HUGE_VAL;
  for (int i = 0; i < cell.numNodes(); ++i) {
    const double d = (cell.position(i) - point).squaredNorm();
    if (d < best) {
      best = d;
      nearest = i;
    }
  }
  return localElementSize(cell, nearest);
}

} // namespace

std::vector<PairSample> pairSamples(const scene::Scene& scene, const std::vector<double>& positions,
                                    const std::vector<CellSample>& samples)
{
  std::vector<PairSample> pairs;
  for (int i = 0; i < scene.numCells(); ++i) {
    for (int j = i + 1; j < scene.numCells(); ++j) {
      const CellSample& a = samples[static_cast<std::size_t>(i)];
      const CellSample& b = samples[static_cast<std::size_t>(j)];
      PairSample pair;
      pair.first = i;
      pair.second = j;
      // The nearest image's separation in a periodic box (domain/Domain.hpp).
      pair.separation = a.shape.centroid - b.shape.centroid;
      scene.description().domain.nearestImage(pair.separation.data());
      pair.distance = pair.separation.norm();
      pair.relativeVelocity = a.instantVelocity - b.instantVelocity;
      pair.relativeSlip = a.slipVelocity() - b.slipVelocity();
      pair.gap = gapBetween(scene, positions, i, j);
      // The cells hold the positions of this output (Scene::evaluate set them).
      const double size =
          std::max(elementSizeNear(scene.cell(i), pair.gap.onFirst), elementSizeNear(scene.cell(j), pair.gap.onSecond));
      pair.gapPerElementSize = size > 0.0 ? pair.gap.distance / size : 0.0;
      pairs.push_back(pair);
    }
  }
  return pairs;
}

std::vector<std::string> pairColumns(int numCells)
{
  std::vector<std::string> columns;
  for (int i = 0; i < numCells; ++i) {
    for (int j = i + 1; j < numCells; ++j) {
      const std::string suffix = "_" + std::to_string(i) + "_" + std::to_string(j);
      for (const char* name : {"dx", "dy", "dz", "distance", "du", "dv", "dw", "dslip", "gap"}) {
        columns.push_back(name + suffix);
      }
    }
  }
  return columns;
}

std::vector<double> pairValues(const PairSample& pair)
{
  return {pair.separation[0],       pair.separation[1],       pair.separation[2],       pair.distance,
          pair.relativeVelocity[0], pair.relativeVelocity[1], pair.relativeVelocity[2], pair.relativeSlip,
          pair.gap.distance};
}

ClosestPair closestPair(const scene::Scene& scene, const std::vector<double>& positions)
{
  ClosestPair closest;
  closest.gap = HUGE_VAL;
  for (int i = 0; i < scene.numCells(); ++i) {
    for (int j = i + 1; j < scene.numCells(); ++j) {
      const double gap = gapBetween(scene, positions, i, j).distance;
      if (gap < closest.gap) {
        closest = {i, j, gap};
      }
    }
  }
  return closest;
}

} // namespace capsula::run
