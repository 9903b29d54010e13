#include "capsula/contour/Contour.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/KernelClones.hpp>

#include <cmath>
#include <cstddef>

namespace capsula::contour {

namespace {

using core::InputError;
using core::require;

Eigen::Matrix2Xd validatedNodes(Eigen::Matrix2Xd nodes)
{
  const Eigen::Index n = nodes.cols();
  require<InputError>(n >= 3, "a contour needs at least 3 nodes, got ", n);
  require<InputError>(nodes.allFinite(), "contour nodes must be finite");
  double twiceSignedArea = 0.0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index next = (k + 1) % n;
    require<InputError>((nodes.col(next) - nodes.col(k)).norm() > 0.0, "contour nodes ", k, " and ", next,
                        " coincide at (", nodes(0, k), ", ", nodes(1, k), "); remove the duplicate");
    twiceSignedArea += nodes(0, k) * nodes(1, next) - nodes(0, next) * nodes(1, k);
  }
  require<InputError>(twiceSignedArea > 0.0, "contour nodes must run counter-clockwise (the polygon's signed area is ",
                      0.5 * twiceSignedArea, "); reverse their order");
  return nodes;
}

// The arc-length sum runs for every load evaluation of the 2D single layer (several
// thousand per right-hand side), so, as the operators' hot loops (RegularSums.hpp), it is
// also compiled for AVX2 and AVX-512 (core/KernelClones.hpp).

/// sum_q w_q |dx/ds| at ds = t tau_q span (Contour::arcLengthAt). |dx/ds| by
/// sqrt(x'^2 + y'^2), not std::hypot: the derivatives are O(1), so nothing can overflow,
/// and hypot's care cost a fifth of the 2D right-hand side. The speeds are formed in a loop
/// without dependencies (it vectorises: -fno-math-errno in CMakeLists.txt), then summed in
/// order. Built without fused multiply-adds (CMakeLists.txt), so every clone returns the same
/// bits.
CAPSULA_KERNEL_CLONES double gaussSpeedSum(const double* tau, const double* weight, std::size_t points, double t,
                                           double span, const CubicPiece& px, const CubicPiece& py)
{
  double speed[64]; // points <= 64 (validatedOptions)
  for (std::size_t q = 0; q < points; ++q) {
    const double ds = t * tau[q] * span;
    const double dx = (3.0 * px.a * ds + 2.0 * px.b) * ds + px.c; // CubicPiece::derivative
    const double dy = (3.0 * py.a * ds + 2.0 * py.b) * ds + py.c;
    speed[q] = std::sqrt(dx * dx + dy * dy);
  }
  double partial = 0.0;
  for (std::size_t q = 0; q < points; ++q) {
    partial += weight[q] * speed[q];
  }
  return partial;
}

ContourOptions validatedOptions(const ContourOptions& options)
{
  require<InputError>(options.arcLengthPoints >= 1 && options.arcLengthPoints <= 64,
                      "contour arcLengthPoints must be between 1 and 64, got ", options.arcLengthPoints);
  return options;
}

/// s_k: cumulative chord length or node index (eq A.14), N + 1 knots.
std::vector<double> knotsFor(const Eigen::Matrix2Xd& nodes, Parametrisation parametrisation)
{
  const Eigen::Index n = nodes.cols();
  std::vector<double> knots(static_cast<std::size_t>(n) + 1, 0.0);
  for (Eigen::Index k = 0; k < n; ++k) {
    const double step =
        parametrisation == Parametrisation::ChordLength ? (nodes.col((k + 1) % n) - nodes.col(k)).norm() : 1.0;
    knots[static_cast<std::size_t>(k) + 1] = knots[static_cast<std::size_t>(k)] + step;
  }
  return knots;
}

CubicSpline fitCoordinate(const Eigen::Matrix2Xd& nodes, const ContourOptions& options, int row)
{
  std::vector<double> knots = knotsFor(nodes, options.parametrisation);
  const Eigen::Index n = nodes.cols();
  std::vector<double> values(static_cast<std::size_t>(n));
  for (Eigen::Index k = 0; k < n; ++k) {
    values[static_cast<std::size_t>(k)] = nodes(row, k);
  }
  if (options.closure == Closure::Periodic) {
    return CubicSpline::periodic(std::move(knots), values);
  }
  // Tethered: open at the tether node, which ends the contour again at s_max.
  values.push_back(nodes(row, 0));
  return options.tetherEnds == TetherEnds::Natural ? CubicSpline::natural(std::move(knots), values)
                                                   : CubicSpline::notAKnot(std::move(knots), values);
}

} // namespace

Contour::Contour(Eigen::Matrix2Xd nodes, ContourOptions options)
    : nodes_(validatedNodes(std::move(nodes))),
      options_(validatedOptions(options)),
      xSpline_(fitCoordinate(nodes_, options_, 0)),
      ySpline_(fitCoordinate(nodes_, options_, 1)),
      arcLengthRule_(quadrature::gaussLegendre(options_.arcLengthPoints))
{
  const int n = numberOfSegments();
  segmentLengths_.resize(static_cast<std::size_t>(n));
  knotArcLengths_.assign(static_cast<std::size_t>(n) + 1, 0.0);
  for (int k = 0; k < n; ++k) {
    const auto index = static_cast<std::size_t>(k);
    segmentLengths_[index] = arcLengthAt(k, 1.0) - knotArcLengths_[index];
    knotArcLengths_[index + 1] = knotArcLengths_[index] + segmentLengths_[index];
  }
}

ContourPoint Contour::pointAt(int segment, double t) const
{
  const std::vector<double>& s = parameters();
  const auto k = static_cast<std::size_t>(segment);
  const double ds = t * (s[k + 1] - s[k]);
  const CubicPiece& px = xSpline_.piece(segment);
  const CubicPiece& py = ySpline_.piece(segment);
  return contourPoint(Eigen::Vector2d(px.value(ds), py.value(ds)),
                      Eigen::Vector2d(px.derivative(ds), py.derivative(ds)),
                      Eigen::Vector2d(px.secondDerivative(ds), py.secondDerivative(ds)));
}

Eigen::Vector2d Contour::positionAt(int segment, double t) const
{
  const std::vector<double>& s = parameters();
  const auto k = static_cast<std::size_t>(segment);
  const double ds = t * (s[k + 1] - s[k]);
  return {xSpline_.piece(segment).value(ds), ySpline_.piece(segment).value(ds)};
}

ContourPoint Contour::pointAtParameter(double s) const
{
  const auto [k, ds] = xSpline_.locate(s);
  const std::vector<double>& knots = parameters();
  const auto index = static_cast<std::size_t>(k);
  return pointAt(k, ds / (knots[index + 1] - knots[index]));
}

Eigen::Matrix2Xd Contour::tangents() const
{
  Eigen::Matrix2Xd result(2, numberOfNodes());
  for (int i = 0; i < numberOfNodes(); ++i) {
    result.col(i) = nodePoint(i).tangent;
  }
  return result;
}

Eigen::Matrix2Xd Contour::normals() const
{
  Eigen::Matrix2Xd result(2, numberOfNodes());
  for (int i = 0; i < numberOfNodes(); ++i) {
    result.col(i) = nodePoint(i).normal;
  }
  return result;
}

Eigen::VectorXd Contour::curvatures() const
{
  Eigen::VectorXd result(numberOfNodes());
  for (int i = 0; i < numberOfNodes(); ++i) {
    result(i) = nodePoint(i).curvature;
  }
  return result;
}

double Contour::arcLengthAt(int segment, double t) const
{
  // int_0^t h(s_k + tau (s_{k+1} - s_k)) (s_{k+1} - s_k) dtau by Gauss-Legendre (eq A.40).
  const std::vector<double>& s = parameters();
  const auto k = static_cast<std::size_t>(segment);
  const double span = s[k + 1] - s[k];
  const double partial =
      gaussSpeedSum(arcLengthRule_.points.data(), arcLengthRule_.weights.data(), arcLengthRule_.points.size(), t, span,
                    xSpline_.piece(segment), ySpline_.piece(segment));
  return knotArcLengths_[k] + partial * t * span;
}

} // namespace capsula::contour
