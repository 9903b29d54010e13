#include "capsula/scene2d/SplineDoubleLayer2D.hpp"

#include "capsula/scene2d/ContourQuadrature2D.hpp"
#include "capsula/scene2d/RegularSums2D.hpp"

#include <capsula/core/Error.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace capsula::scene2d {

void SplineDoubleLayer2D::reset(int numNodes, bool periodic, int paddedTargets)
{
  core::require(numNodes >= 3 && paddedTargets >= 0 && paddedTargets % operators::targetLaneMultiple == 0,
                "SplineDoubleLayer2D: ", numNodes, " nodes and ", paddedTargets, " target lanes");
  periodic_ = periodic;
  numKnots_ = periodic ? numNodes : numNodes + 1;
  paddedTargets_ = paddedTargets;
  coefficients_.assign(static_cast<std::size_t>(numKnots_) * 8 * static_cast<std::size_t>(paddedTargets), 0.0);
  sums_.assign(4 * static_cast<std::size_t>(paddedTargets), 0.0);
}

void SplineDoubleLayer2D::addPoint(int t, int k, double tau, double h, const double W[4])
{
  double b[4];
  splineBasis(tau, h, b);
  const auto lanes = static_cast<std::size_t>(paddedTargets_);
  double* left = &coefficients_[8 * static_cast<std::size_t>(k) * lanes + static_cast<std::size_t>(t)];
  double* right = &coefficients_[8 * static_cast<std::size_t>(rightKnot(k)) * lanes + static_cast<std::size_t>(t)];
  for (int c = 0; c < 4; ++c) {
    left[c * lanes] += b[0] * W[c];
    left[(4 + c) * lanes] += b[2] * W[c];
    right[c * lanes] += b[1] * W[c];
    right[(4 + c) * lanes] += b[3] * W[c];
    sums_[c * lanes + static_cast<std::size_t>(t)] += W[c];
  }
}

namespace {

// rx[t], ry[t] += sum over the knots of u_i A_ij + M_i B_ij (the targets innermost: no
// reduction, so it vectorises without reordering any target's sum).
CAPSULA_KERNEL_CLONES void sumOverKnots(const double* knotData, const double* coefficients, int numKnots, int lanes,
                                        double* __restrict rx, double* __restrict ry)
{
  for (int k = 0; k < numKnots; ++k) {
    const double* d = knotData + 4 * k;
    const double ux = d[0], uy = d[1], mx = d[2], my = d[3];
    const double* A = coefficients + 8L * k * lanes;
    for (int t = 0; t < lanes; ++t) {
      rx[t] += ux * A[t] + uy * A[2 * lanes + t] + mx * A[4 * lanes + t] + my * A[6 * lanes + t];
      ry[t] += ux * A[lanes + t] + uy * A[3 * lanes + t] + mx * A[5 * lanes + t] + my * A[7 * lanes + t];
    }
  }
}

} // namespace

void SplineDoubleLayer2D::apply(const contour::Contour& contour, const double* nodalDensity, bool subtract,
                                int firstTarget, int numTargets, double* result) const
{
  // The density's spline (the one ContourField2D evaluates): knot values and second
  // derivatives, M_k = 2 b_k on piece k and M_n = 6 a h + 2 b at the end of the last.
  const ContourField2D field(contour, nodalDensity);
  const std::vector<double>& s = contour.parameters();
  const int numNodes = contour.numberOfNodes();
  knotData_.resize(4 * static_cast<std::size_t>(numKnots_));
  for (int c = 0; c < 2; ++c) {
    const contour::CubicSpline& spline = field.component(c);
    for (int k = 0; k < numKnots_; ++k) {
      const int node = k % numNodes; // the tethered contour's last knot is the tether node
      knotData_[4 * static_cast<std::size_t>(k) + static_cast<std::size_t>(c)] = nodalDensity[2 * node + c];
      const int piece = std::min(k, spline.numberOfPieces() - 1);
      const contour::CubicPiece& p = spline.piece(piece);
      const double h = s[static_cast<std::size_t>(piece) + 1] - s[static_cast<std::size_t>(piece)];
      knotData_[4 * static_cast<std::size_t>(k) + 2 + static_cast<std::size_t>(c)] =
          k == piece ? 2.0 * p.b : 6.0 * p.a * h + 2.0 * p.b;
    }
  }
  const auto lanes = static_cast<std::size_t>(paddedTargets_);
  sumX_.assign(lanes, 0.0);
  sumY_.assign(lanes, 0.0);
  double* rx = sumX_.data();
  double* ry = sumY_.data();
  sumOverKnots(knotData_.data(), coefficients_.data(), numKnots_, paddedTargets_, rx, ry);
  for (int t = 0; t < numTargets; ++t) {
    const auto lane = static_cast<std::size_t>(t);
    double x = rx[lane], y = ry[lane];
    if (subtract) {
      // int [u - u(x_t)] T n dl - 2 pi u(x_t): PV int T n dl = -2 pi on the contour.
      const int m = firstTarget + t;
      const double u0 = nodalDensity[2 * m], u1 = nodalDensity[2 * m + 1];
      x -= u0 * sums_[lane] + u1 * sums_[2 * lanes + lane] + 2.0 * M_PI * u0;
      y -= u0 * sums_[lanes + lane] + u1 * sums_[3 * lanes + lane] + 2.0 * M_PI * u1;
    }
    result[2 * t] = x;
    result[2 * t + 1] = y;
  }
}

namespace {

// Regular pairs, targets in blocks held in local accumulators (20 rows: A and B of the
// segment's two knots, and the sums), so that the coefficient arrays are touched once per
// segment and block rather than once per point. Always inlined into the target clones
// below: a separate instance would be compiled for the baseline instruction set only.
template <class Weight>
[[gnu::always_inline]] inline void coefficientsOfSegments(const double* px, const double* py, const double* ax,
                                                          const double* ay, const double* basis, int pointsPerSegment,
                                                          int numSegments, const double* tx, const double* ty,
                                                          const double* mask, SplineDoubleLayer2D& layer, Weight weight)
{
  constexpr int block = 64;
  const int lanes = layer.paddedTargets();
  double* coefficients = layer.coefficients();
  double* sums = layer.sums();
  alignas(64) double acc[20][block];
  for (int k = 0; k < numSegments; ++k) {
    const double* use = mask + static_cast<long>(k) * lanes;
    double* left = coefficients + 8L * k * lanes;
    double* right = coefficients + 8L * layer.rightKnot(k) * lanes;
    for (int first = 0; first < lanes; first += block) {
      const int count = std::min(block, lanes - first);
      for (auto& row : acc) {
        std::fill(row, row + count, 0.0);
      }
      for (int p = k * pointsPerSegment; p < (k + 1) * pointsPerSegment; ++p) {
        const double x = px[p], y = py[p], a0 = ax[p], a1 = ay[p];
        const double b0 = basis[4 * p], b1 = basis[4 * p + 1], b2 = basis[4 * p + 2], b3 = basis[4 * p + 3];
        for (int i = 0; i < count; ++i) {
          double W[4];
          weight(x, y, a0, a1, tx[first + i], ty[first + i], W);
          const double m = use[first + i];
          for (int c = 0; c < 4; ++c) {
            const double w = m * W[c];
            acc[c][i] += b0 * w;
            acc[4 + c][i] += b2 * w;
            acc[8 + c][i] += b1 * w;
            acc[12 + c][i] += b3 * w;
            acc[16 + c][i] += w;
          }
        }
      }
      for (int c = 0; c < 8; ++c) {
        for (int i = 0; i < count; ++i) {
          left[c * lanes + first + i] += acc[c][i];
          right[c * lanes + first + i] += acc[8 + c][i];
        }
      }
      for (int c = 0; c < 4; ++c) {
        for (int i = 0; i < count; ++i) {
          sums[c * lanes + first + i] += acc[16 + c][i];
        }
      }
    }
  }
}

using DoubleLayerWeight2D = void (*)(double, double, double, double, double, double, double[4]);

// One clone set for each kernel's weight W_ij (RegularSums2D.hpp); the weight is a template
// argument called from a lambda, not a function pointer passed on, so that the pair
// formula inlines into the loop.
template <DoubleLayerWeight2D doubleLayerWeight>
CAPSULA_KERNEL_CLONES void doubleLayerCoefficients(const double* px, const double* py, const double* ax,
                                                   const double* ay, const double* basis, int pointsPerSegment,
                                                   int numSegments, const double* tx, const double* ty,
                                                   const double* mask, SplineDoubleLayer2D& layer)
{
  coefficientsOfSegments(px, py, ax, ay, basis, pointsPerSegment, numSegments, tx, ty, mask, layer,
                         [](double x, double y, double a0, double a1, double x0, double y0, double W[4]) {
                           doubleLayerWeight(x, y, a0, a1, x0, y0, W);
                         });
}

} // namespace

void addWallDoubleLayerCoefficients2D(const double* px, const double* py, const double* ax, const double* ay,
                                      const double* basis, int pointsPerSegment, int numSegments, const double* tx,
                                      const double* ty, const double* mask, SplineDoubleLayer2D& layer)
{
  doubleLayerCoefficients<wallDoubleLayerWeight2D>(px, py, ax, ay, basis, pointsPerSegment, numSegments, tx, ty, mask,
                                                   layer);
}

void addFreeSpaceDoubleLayerCoefficients2D(const double* px, const double* py, const double* ax, const double* ay,
                                           const double* basis, int pointsPerSegment, int numSegments, const double* tx,
                                           const double* ty, const double* mask, SplineDoubleLayer2D& layer)
{
  doubleLayerCoefficients<freeSpaceDoubleLayerWeight2D>(px, py, ax, ay, basis, pointsPerSegment, numSegments, tx, ty,
                                                        mask, layer);
}

} // namespace capsula::scene2d
