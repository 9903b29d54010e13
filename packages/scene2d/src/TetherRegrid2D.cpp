#include "capsula/scene2d/TetherRegrid2D.hpp"

#include "capsula/scene2d/MaterialArcLength2D.hpp"

#include <capsula/contour/ContourLocation.hpp>
#include <capsula/core/Error.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace capsula::scene2d {

namespace {

/// The spacing of one half of the contour, from the tether (d = 0) to the opposite point
/// (d = half): h(d) = H psi(d), psi(d) = min(1, f + (1 - f) d / w).
struct HalfGrading {
  double f = 0.0;
  double w = 0.0;
  double half = 0.0;
  double H = 0.0;

  double graded() const { return std::min(w, half); }
  /// int_0^d dd / psi for d <= graded(), and beyond it.
  double integral(double d) const
  {
    const double slope = (1.0 - f) / w;
    const double g = graded();
    if (d <= g) {
      return std::log1p(slope * d / f) / slope;
    }
    return std::log1p(slope * g / f) / slope + (d - g);
  }
  /// The d at which int_0^d dd / h = markers (the inverse of integral(d) / H).
  double distance(double markers) const
  {
    const double slope = (1.0 - f) / w;
    const double g = graded();
    const double reduced = markers * H;
    const double atGraded = integral(g);
    if (reduced <= atGraded) {
      return f * std::expm1(slope * reduced) / slope;
    }
    return g + (reduced - atGraded);
  }
};

} // namespace

std::vector<double> gradedArcLengths(int markers, double length, const TetherGrading2D& grading)
{
  core::require<core::InputError>(markers >= 4 && length > 0.0, "gradedArcLengths: ", markers,
                                  " markers over a length ", length);
  core::require<core::InputError>(grading.tetherSpacing > 0.0 && grading.tetherSpacing <= 1.0,
                                  "Tether/Spacing at the tether must lie in (0, 1] (a fraction of the far "
                                  "spacing), got ",
                                  grading.tetherSpacing);
  core::require<core::InputError>(grading.gradedLength > 0.0, "Tether/Graded length must be > 0, got ",
                                  grading.gradedLength);
  HalfGrading half;
  half.f = grading.tetherSpacing;
  half.w = grading.gradedLength;
  half.half = 0.5 * length;
  // N / 2 markers per half: int_0^half dd / (H psi) = N / 2 fixes the far spacing H.
  half.H = half.f == 1.0 ? length / markers : 2.0 * half.integral(half.half) / markers;

  std::vector<double> sigma(static_cast<std::size_t>(markers) + 1);
  for (int j = 0; 2 * j <= markers; ++j) {
    const double d = half.f == 1.0 ? j * half.H : half.distance(j);
    sigma[static_cast<std::size_t>(j)] = d;
    sigma[static_cast<std::size_t>(markers - j)] = length - d;
  }
  sigma.front() = 0.0;
  sigma.back() = length;
  return sigma;
}

TetherRegrid2D regridTowardsLowestPoint(const contour::Contour& reference, const contour::Contour& current,
                                        const TetherGrading2D& grading)
{
  core::require<core::InputError>(reference.closure() == contour::Closure::Periodic &&
                                      current.closure() == contour::Closure::Periodic &&
                                      reference.numberOfNodes() == current.numberOfNodes(),
                                  "regridTowardsLowestPoint: the reference and the free cell must be periodic contours "
                                  "through the same markers");
  const int n = current.numberOfNodes();
  const MaterialArcLength2D material(reference.knotArcLengths(), current.knotArcLengths(), contour::Closure::Periodic);
  TetherRegrid2D result;
  const contour::ContourLocation lowest = contour::lowestPoint(current);
  result.tetherArcLength = current.arcLengthAt(lowest.segment, lowest.t);
  result.tetherReferenceArcLength = material.referenceArcLength(result.tetherArcLength);

  const std::vector<double> sigma = gradedArcLengths(n, reference.length(), grading);
  result.referenceNodes.resize(2, n);
  result.currentNodes.resize(2, n);
  for (int j = 0; j < n; ++j) {
    const double l0 = result.tetherReferenceArcLength + sigma[static_cast<std::size_t>(j)];
    const contour::ContourLocation atReference = contour::locateArcLength(reference, l0);
    result.referenceNodes.col(j) = reference.positionAt(atReference.segment, atReference.t);
    const contour::ContourLocation atCurrent = contour::locateArcLength(current, material.currentArcLength(l0));
    result.currentNodes.col(j) = current.positionAt(atCurrent.segment, atCurrent.t);
  }
  // Node 0 is the lowest point itself (not its round trip through l(l0) and back).
  result.currentNodes.col(0) = current.positionAt(lowest.segment, lowest.t);
  return result;
}

TetherRegrid2D regridAtTether(const contour::Contour& reference, const contour::Contour& current,
                              const TetherGrading2D& grading, const Eigen::Vector2d& anchor)
{
  TetherRegrid2D result = regridTowardsLowestPoint(reference, current, grading);
  const Eigen::Vector2d shift = anchor - result.currentNodes.col(0);
  result.currentNodes.colwise() += shift;
  return result;
}

} // namespace capsula::scene2d
