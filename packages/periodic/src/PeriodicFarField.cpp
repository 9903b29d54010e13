#include "capsula/periodic/PeriodicFarField.hpp"

#include <capsula/ewald/SpectralEwald2P.hpp>
#include <capsula/ewald/SpectralEwaldChannel2P.hpp>
#include <capsula/ewald/SpectralEwaldChannelStresslet2P.hpp>
#include <capsula/ewald/SpectralEwaldStresslet2P.hpp>
#include <capsula/ewald/SpectralEwaldWall2P.hpp>
#include <capsula/ewald/SpectralEwaldWallStresslet2P.hpp>
#include <capsula/operators/DirectSummation.hpp>
#include <capsula/operators/RegularSums.hpp>

#include <algorithm>

namespace capsula::periodic {

PeriodicFarField::PeriodicFarField(const PeriodicBox& box, double tolerance, PeriodicFluid fluid, double channelHeight)
    : box_(box), tolerance_(tolerance), fluid_(fluid), channelHeight_(channelHeight)
{}

void PeriodicFarField::setSources(const double* x, const double* y, const double* z,
                                  const std::vector<int>& cellPointOffsets)
{
  x_ = x;
  y_ = y;
  z_ = z;
  offsets_ = cellPointOffsets;
  ownTargets_.clear(); // new geometry: the own-cell blocks are summed again
  ownTargetCells_.clear();
  const int numPoints = offsets_.empty() ? 0 : offsets_.back();
  folded_.resize(3 * static_cast<std::size_t>(numPoints));
  for (int q = 0; q < numPoints; ++q) {
    const double point[3] = {x[q], y[q], z[q]};
    box_.fold(point, &folded_[3 * static_cast<std::size_t>(q)]);
  }
}

std::vector<double> PeriodicFarField::foldedTargets(const double* targets, int n) const
{
  std::vector<double> folded(3 * static_cast<std::size_t>(n));
  for (int t = 0; t < n; ++t) {
    box_.fold(targets + 3 * t, &folded[3 * static_cast<std::size_t>(t)]);
  }
  return folded;
}

void PeriodicFarField::singleLayer(const operators::SingleLayerSources& sources, const double* targets, int n,
                                   double* result)
{
  if (n == 0) {
    return;
  }
  const std::size_t numPoints = folded_.size() / 3;
  std::vector<double> forces(3 * numPoints);
  for (std::size_t q = 0; q < numPoints; ++q) {
    forces[3 * q] = sources.fx[q];
    forces[3 * q + 1] = sources.fy[q];
    forces[3 * q + 2] = sources.fz[q];
  }
  const ewald::PeriodicLayer layer{box_.lengthX, box_.lengthZ};
  const std::vector<double> folded = foldedTargets(targets, n);
  std::vector<double> u;
  switch (fluid_) {
  case PeriodicFluid::Unbounded:
    u = ewald::spectralEwald2P(layer, tolerance_, folded_, forces, folded);
    break;
  case PeriodicFluid::AboveWall:
    u = ewald::spectralEwaldWall2P(layer, tolerance_, folded_, forces, folded);
    break;
  case PeriodicFluid::Channel:
    u = ewald::spectralEwaldChannel2P(layer, channelHeight_, tolerance_, folded_, forces, folded);
    break;
  }
  std::copy(u.begin(), u.end(), result);
}

void PeriodicFarField::doubleLayer(const operators::DoubleLayerSources& sources, const double* targets,
                                   const int* targetCells, const double* subtracted, int n, double* result)
{
  if (n == 0) {
    return;
  }
  const std::size_t numPoints = folded_.size() / 3;
  std::vector<double> tensors(9 * numPoints);
  for (std::size_t q = 0; q < numPoints; ++q) {
    const double v[3] = {sources.vx[q], sources.vy[q], sources.vz[q]};
    const double a[3] = {sources.ax[q], sources.ay[q], sources.az[q]};
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) {
        tensors[9 * q + 3 * i + k] = v[i] * a[k];
      }
    }
  }
  const ewald::PeriodicLayer layer{box_.lengthX, box_.lengthZ};
  const std::vector<double> folded = foldedTargets(targets, n);
  std::vector<double> u;
  switch (fluid_) {
  case PeriodicFluid::Unbounded:
    // sum_q T(x_q - x_t) S_q = -sum_q T(x_t - x_q) S_q (T odd).
    u = ewald::spectralEwaldStresslet2P(layer, tolerance_, folded_, tensors, folded);
    for (double& component : u) {
      component = -component;
    }
    break;
  case PeriodicFluid::AboveWall:
    u = ewald::spectralEwaldWallStresslet2P(layer, tolerance_, folded_, tensors, folded);
    break;
  case PeriodicFluid::Channel:
    u = ewald::spectralEwaldChannelStresslet2P(layer, channelHeight_, tolerance_, folded_, tensors, folded);
    break;
  }
  if (!targetCells) {
    std::copy(u.begin(), u.end(), result);
    return;
  }
  // - s_t sum_{own cell} T a_q with the local kernel, from the blocks of the geometry.
  const std::vector<double>& blocks = ownCellBlocks(sources, targets, targetCells, n);
  for (int t = 0; t < n; ++t) {
    const double* s = subtracted + 3 * t;
    const double* B = &blocks[9 * static_cast<std::size_t>(t)];
    for (int j = 0; j < 3; ++j) {
      result[3 * t + j] = u[3 * t + j] + s[0] * B[j] + s[1] * B[3 + j] + s[2] * B[6 + j];
    }
  }
}

const std::vector<double>& PeriodicFarField::ownCellBlocks(const operators::DoubleLayerSources& sources,
                                                           const double* targets, const int* targetCells, int n)
{
  const std::size_t count = static_cast<std::size_t>(n);
  if (ownTargets_.size() == 3 * count && std::equal(ownTargets_.begin(), ownTargets_.end(), targets) &&
      std::equal(ownTargetCells_.begin(), ownTargetCells_.end(), targetCells)) {
    return ownBlocks_;
  }
  ownTargets_.assign(targets, targets + 3 * count);
  ownTargetCells_.assign(targetCells, targetCells + count);
  ownBlocks_.assign(9 * count, 0.0);
  // The direct sums of the subtracted form with zero density give -sum_{own cell} T (s_t) a_q
  // (forTargetBlocks writes them to `column`), once for each unit vector s_t = e_i.
  const std::size_t numPoints = folded_.size() / 3;
  const std::vector<double> zero(numPoints, 0.0);
  const operators::DoubleLayerSources own{x_,         y_,          z_,          sources.ax, sources.ay,
                                          sources.az, zero.data(), zero.data(), zero.data()};
  std::vector<double> unit(3 * count, 0.0), column(3 * count);
  for (int i = 0; i < 3; ++i) {
    for (std::size_t t = 0; t < count; ++t) {
      unit[3 * t] = unit[3 * t + 1] = unit[3 * t + 2] = 0.0;
      unit[3 * t + i] = 1.0;
    }
    operators::forTargetBlocks(
        targets, targetCells, unit.data(), n, column.data(), [&](operators::TargetBlock& block, int cell) {
          const int begin = offsets_[cell], end = offsets_[cell + 1];
          switch (fluid_) {
          case PeriodicFluid::Unbounded:
            operators::addDoubleLayerSums<operators::FreeSpace3DKernel, true>(block, own, begin, end);
            break;
          case PeriodicFluid::AboveWall:
            operators::addDoubleLayerSums<operators::Wall3DKernel, true>(block, own, begin, end);
            break;
          case PeriodicFluid::Channel:
            operators::addDoubleLayerSums<NearestWallKernel, true>(NearestWallKernel{channelHeight_}, block, own, begin,
                                                                   end);
            break;
          }
        });
    for (std::size_t t = 0; t < count; ++t) {
      for (int j = 0; j < 3; ++j) {
        ownBlocks_[9 * t + 3 * i + j] = column[3 * t + j];
      }
    }
  }
  return ownBlocks_;
}

std::unique_ptr<operators::FarFieldSummation> PeriodicFreeSpaceKernel::farFieldSummation() const
{
  return std::make_unique<PeriodicFarField>(box, tolerance, PeriodicFluid::Unbounded);
}

std::unique_ptr<operators::FarFieldSummation> PeriodicWallKernel::farFieldSummation() const
{
  return std::make_unique<PeriodicFarField>(box, tolerance, PeriodicFluid::AboveWall);
}

std::unique_ptr<operators::FarFieldSummation> PeriodicChannelKernel::farFieldSummation() const
{
  return std::make_unique<PeriodicFarField>(box, tolerance, PeriodicFluid::Channel, local.height);
}

} // namespace capsula::periodic
