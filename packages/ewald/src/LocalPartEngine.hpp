#pragma once
// The local part of a spectral Ewald sum in a 2P layer (SpectralEwald2P.hpp), for any kernel:
// Kernel::add(xh, r2, density, u) adds the screened kernel's contribution of one source (C
// numbers of density) at displacement xh = x_t - x_n - p, |xh|^2 = r2 < r_c^2 (r2 = 0 for a target
// on the source: the kernel adds its regular limit there). The sources are found with a cell
// list periodic in x and z (cells at least r_c wide, so a target looks at the neighbouring cells
// and, where a period is shorter than r_c, at as many images of them as reach r_c).
#include "capsula/ewald/SpectralEwald2P.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace capsula::ewald::detail {

/// x folded into [0, L).
inline double foldPeriodic(double x, double length)
{
  const double folded = x - length * std::floor(x / length);
  return folded < length ? folded : 0.0;
}

inline int wrapIndex(int i, int n)
{
  return ((i % n) + n) % n;
}

/// The sources sorted by cell; cell c holds slots start[c] .. start[c + 1] - 1.
struct CellList {
  int cellsX = 1, cellsY = 1, cellsZ = 1;
  double sizeX = 0.0, sizeY = 0.0, sizeZ = 0.0, yMin = 0.0;
  std::vector<int> start;
  std::vector<double> position; // folded, in cell order, 3 per source
  std::vector<double> density;  // in cell order, `components` per source

  int cellOf(int ix, int iy, int iz) const { return (ix * cellsY + iy) * cellsZ + iz; }
};

inline CellList buildCellList(const PeriodicLayer& layer, double rc, const std::vector<double>& sources,
                              const std::vector<double>& densities, int components)
{
  const int count = static_cast<int>(sources.size() / 3);
  CellList list;
  double yMin = sources[1], yMax = sources[1];
  for (int n = 0; n < count; ++n) {
    yMin = std::min(yMin, sources[3 * n + 1]);
    yMax = std::max(yMax, sources[3 * n + 1]);
  }
  list.cellsX = std::max(1, static_cast<int>(layer.lengthX / rc));
  list.cellsZ = std::max(1, static_cast<int>(layer.lengthZ / rc));
  list.cellsY = static_cast<int>((yMax - yMin) / rc) + 1;
  list.sizeX = layer.lengthX / list.cellsX;
  list.sizeZ = layer.lengthZ / list.cellsZ;
  list.sizeY = rc;
  list.yMin = yMin;
  std::vector<int> cellOfSource(count);
  list.start.assign(list.cellsX * list.cellsY * list.cellsZ + 1, 0);
  for (int n = 0; n < count; ++n) {
    const int ix =
        std::min(list.cellsX - 1, static_cast<int>(foldPeriodic(sources[3 * n], layer.lengthX) / list.sizeX));
    const int iz =
        std::min(list.cellsZ - 1, static_cast<int>(foldPeriodic(sources[3 * n + 2], layer.lengthZ) / list.sizeZ));
    const int iy = std::min(list.cellsY - 1, static_cast<int>((sources[3 * n + 1] - yMin) / rc));
    cellOfSource[n] = list.cellOf(ix, iy, iz);
    ++list.start[cellOfSource[n] + 1];
  }
  for (std::size_t c = 1; c < list.start.size(); ++c) {
    list.start[c] += list.start[c - 1];
  }
  std::vector<int> next(list.start.begin(), list.start.end() - 1);
  list.position.resize(3 * count);
  list.density.resize(static_cast<std::size_t>(components) * count);
  for (int n = 0; n < count; ++n) {
    const int slot = next[cellOfSource[n]]++;
    list.position[3 * slot] = foldPeriodic(sources[3 * n], layer.lengthX);
    list.position[3 * slot + 1] = sources[3 * n + 1];
    list.position[3 * slot + 2] = foldPeriodic(sources[3 * n + 2], layer.lengthZ);
    for (int c = 0; c < components; ++c) {
      list.density[components * slot + c] = densities[components * n + c];
    }
  }
  return list;
}

/// u_t += sum over sources and images within r_c of the kernel's local part.
template <class Kernel>
void addLocalPart(const PeriodicLayer& layer, const SpectralEwaldSettings& settings, const std::vector<double>& sources,
                  const std::vector<double>& densities, const std::vector<double>& targets,
                  std::vector<double>& velocities)
{
  constexpr int C = Kernel::sourceComponents;
  if (sources.empty()) {
    return;
  }
  const double rc = settings.realCutoff;
  const CellList list = buildCellList(layer, rc, sources, densities, C);
  const int reachX = static_cast<int>(std::ceil(rc / list.sizeX));
  const int reachZ = static_cast<int>(std::ceil(rc / list.sizeZ));
  const int targetCount = static_cast<int>(targets.size() / 3);
  for (int t = 0; t < targetCount; ++t) {
    const double x[3] = {foldPeriodic(targets[3 * t], layer.lengthX), targets[3 * t + 1],
                         foldPeriodic(targets[3 * t + 2], layer.lengthZ)};
    const int cx = std::min(list.cellsX - 1, static_cast<int>(x[0] / list.sizeX));
    const int cz = std::min(list.cellsZ - 1, static_cast<int>(x[2] / list.sizeZ));
    const int cy = static_cast<int>(std::floor((x[1] - list.yMin) / rc));
    double u[3] = {0.0, 0.0, 0.0};
    for (int iy = std::max(0, cy - 1); iy <= std::min(list.cellsY - 1, cy + 1); ++iy) {
      for (int ox = -reachX; ox <= reachX; ++ox) {
        const int ix = cx + ox;
        const double shiftX = layer.lengthX * std::floor(static_cast<double>(ix) / list.cellsX);
        for (int oz = -reachZ; oz <= reachZ; ++oz) {
          const int iz = cz + oz;
          const double shiftZ = layer.lengthZ * std::floor(static_cast<double>(iz) / list.cellsZ);
          const int cell = list.cellOf(wrapIndex(ix, list.cellsX), iy, wrapIndex(iz, list.cellsZ));
          for (int slot = list.start[cell]; slot < list.start[cell + 1]; ++slot) {
            const double xh[3] = {x[0] - list.position[3 * slot] - shiftX, x[1] - list.position[3 * slot + 1],
                                  x[2] - list.position[3 * slot + 2] - shiftZ};
            const double r2 = xh[0] * xh[0] + xh[1] * xh[1] + xh[2] * xh[2];
            if (r2 < rc * rc) {
              Kernel::add(xh, r2, settings.xi, &list.density[C * slot], u);
            }
          }
        }
      }
    }
    for (int i = 0; i < 3; ++i) {
      velocities[3 * t + i] += u[i];
    }
  }
}

} // namespace capsula::ewald::detail
