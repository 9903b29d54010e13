#include "GaussianGridding.hpp"

#include <capsula/core/KernelClones.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace capsula::ewald::detail {

namespace {

constexpr double griddingPi = 3.14159265358979323846;

/// The grid points a Gaussian centred at x reaches along one axis: the first index (not yet
/// wrapped) and the weights e^{-alpha (x_i - x)^2}.
struct AxisStencil {
  int first = 0;
  std::vector<double> weight; // reused from point to point: no allocation once it has grown

  void set(double x, double origin, double spacing, double radius, double alpha)
  {
    first = static_cast<int>(std::ceil((x - radius - origin) / spacing));
    const int last = static_cast<int>(std::floor((x + radius - origin) / spacing));
    weight.resize(static_cast<std::size_t>(std::max(0, last - first + 1)));
    for (std::size_t k = 0; k < weight.size(); ++k) {
      const double d = origin + (first + static_cast<int>(k)) * spacing - x;
      weight[k] = std::exp(-alpha * d * d);
    }
  }
  int count() const { return static_cast<int>(weight.size()); }
};

/// A contiguous piece of a z stencil on the periodic grid: stencil entries [offset, offset +
/// length) fall on the grid points [start, start + length) of a row.
struct ZRun {
  int start, offset, length;
};

/// Cuts the z stencil into contiguous runs of the grid (one, or more where it wraps).
void zRuns(const AxisStencil& z, int gridZ, std::vector<ZRun>& runs)
{
  runs.clear();
  for (int offset = 0; offset < z.count();) {
    const int start = ((z.first + offset) % gridZ + gridZ) % gridZ;
    const int length = std::min(z.count() - offset, gridZ - start);
    runs.push_back({start, offset, length});
    offset += length;
  }
}

/// One point's Gaussian on the grid: the (x, y) rows it reaches (the index of each row's z = 0
/// point and its xy weight) and its z stencil, cut into the grid's contiguous runs.
struct GridFootprint {
  std::vector<std::size_t> rows;
  std::vector<double> rowWeights;
  std::vector<ZRun> runs;
  const double* wz = nullptr;
};

/// grids[c][row + z] += rowWeight q[c] wz over the footprint (the hot loop of a spread).
CAPSULA_KERNEL_CLONES void spreadFootprint(const GridFootprint& footprint, const double* q, int components,
                                           double* const* grids)
{
  const double* __restrict wz = footprint.wz;
  for (std::size_t r = 0; r < footprint.rows.size(); ++r) {
    for (int c = 0; c < components; ++c) {
      const double f = footprint.rowWeights[r] * q[c];
      for (const ZRun& run : footprint.runs) {
        double* __restrict g = grids[c] + footprint.rows[r] + run.start;
        const double* __restrict w = wz + run.offset;
        for (int k = 0; k < run.length; ++k) {
          g[k] += f * w[k];
        }
      }
    }
  }
}

/// columns[c][z offset] += rowWeight grids[c][row + z] over the footprint, c < 3 (the hot
/// loop of a gather).
CAPSULA_KERNEL_CLONES void gatherFootprint(const GridFootprint& footprint, const double* const* grids, double* columns,
                                           std::size_t countZ)
{
  for (std::size_t r = 0; r < footprint.rows.size(); ++r) {
    const double weight = footprint.rowWeights[r];
    for (int c = 0; c < 3; ++c) {
      for (const ZRun& run : footprint.runs) {
        const double* __restrict g = grids[c] + footprint.rows[r] + run.start;
        double* __restrict a = columns + static_cast<std::size_t>(c) * countZ + run.offset;
        for (int k = 0; k < run.length; ++k) {
          a[k] += weight * g[k];
        }
      }
    }
  }
}

/// Grid points along each axis of the blocks that order the points (gridOrder).
constexpr int orderBlock = 4;

/// The points block by block of orderBlock^3 grid cells (y blocks outermost, then x, then z, as
/// the grid), so that consecutive points share most of their footprints and find them in cache:
/// a Gaussian reaches P^3 points (P = 13 at tolerance 1e-6) of every component's grid.
std::vector<std::size_t> gridOrder(const SpectralEwaldSettings& s, const std::vector<double>& points)
{
  const std::size_t count = points.size() / 3;
  const double lengthX = s.gridX * s.spacingX, lengthZ = s.gridZ * s.spacingZ;
  const long long blocksX = s.gridX / orderBlock + 1, blocksZ = s.gridZ / orderBlock + 1;
  std::vector<std::size_t> order(count);
  std::vector<long long> key(count);
  for (std::size_t n = 0; n < count; ++n) {
    order[n] = n;
    const double x = points[3 * n] - lengthX * std::floor(points[3 * n] / lengthX);
    const double z = points[3 * n + 2] - lengthZ * std::floor(points[3 * n + 2] / lengthZ);
    const auto i = static_cast<long long>(x / s.spacingX) / orderBlock;
    const auto j = static_cast<long long>(std::floor((points[3 * n + 1] - s.yOrigin) / s.spacingY)) / orderBlock;
    const auto l = static_cast<long long>(z / s.spacingZ) / orderBlock;
    key[n] = (j * blocksX + i) * blocksZ + l;
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
  return order;
}

/// The footprint of the Gaussian of each point in turn.
class PointGaussian {
public:
  explicit PointGaussian(const SpectralEwaldSettings& s)
      : s_(s), normalisation_(std::pow(s.gaussianExponent / griddingPi, 1.5))
  {}

  const GridFootprint& centre(const double* x)
  {
    const double alpha = s_.gaussianExponent;
    x_.set(x[0], 0.0, s_.spacingX, s_.supportRadius, alpha);
    y_.set(x[1], s_.yOrigin, s_.spacingY, s_.supportRadius, alpha);
    z_.set(x[2], 0.0, s_.spacingZ, s_.supportRadius, alpha);
    zRuns(z_, s_.gridZ, footprint_.runs);
    footprint_.rows.clear();
    footprint_.rowWeights.clear();
    for (int b = 0; b < y_.count(); ++b) {
      const int j = y_.first + b;
      for (int a = 0; a < x_.count(); ++a) {
        const int i = ((x_.first + a) % s_.gridX + s_.gridX) % s_.gridX;
        footprint_.rows.push_back((static_cast<std::size_t>(j) * s_.gridX + i) * s_.gridZ);
        footprint_.rowWeights.push_back(normalisation_ * x_.weight[static_cast<std::size_t>(a)] *
                                        y_.weight[static_cast<std::size_t>(b)]);
      }
    }
    footprint_.wz = z_.weight.data();
    return footprint_;
  }

  const AxisStencil& z() const { return z_; }

private:
  const SpectralEwaldSettings& s_;
  double normalisation_;
  AxisStencil x_, y_, z_;
  GridFootprint footprint_;
};

} // namespace

void spreadOnGrid(const SpectralEwaldSettings& s, const std::vector<double>& points,
                  const std::vector<double>& densities, int components, double* const* grids)
{
  PointGaussian gaussian(s);
  for (const std::size_t n : gridOrder(s, points)) {
    spreadFootprint(gaussian.centre(&points[3 * n]), &densities[static_cast<std::size_t>(components) * n], components,
                    grids);
  }
}

void gatherFromGrid(const SpectralEwaldSettings& s, const std::vector<double>& points, const double* const* grids,
                    double scale, std::vector<double>& values)
{
  PointGaussian gaussian(s);
  std::vector<double> columns; // [c][z offset]: the xy-weighted sums of each z offset
  for (const std::size_t t : gridOrder(s, points)) {
    const GridFootprint& footprint = gaussian.centre(&points[3 * t]);
    const auto countZ = static_cast<std::size_t>(gaussian.z().count());
    columns.assign(3 * countZ, 0.0);
    gatherFootprint(footprint, grids, columns.data(), countZ);
    for (std::size_t c = 0; c < 3; ++c) {
      double u = 0.0;
      for (std::size_t k = 0; k < countZ; ++k) {
        u += columns[c * countZ + k] * footprint.wz[k];
      }
      values[3 * t + c] += scale * u;
    }
  }
}

} // namespace capsula::ewald::detail
