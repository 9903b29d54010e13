#pragma once
// The single- and double-layer integrals of the 2D boundary-integral equation (thesis
// eq A.35) over a cubic-spline contour, for one Green's function policy (greens::FreeSpace2D,
// greens::Wall2D), at the nodes this rank owns and at arbitrary points.
//
// Single layer  SL_j(x0) = int_C f_i(x) G_ij(x, x0) dl(x), f given at any contour point
// (a load such as Delta f, through the membrane's tension spline). When x0 is node m, the
// two segments that end there carry G ~ -delta_ij ln r. On each of them, with tau in
// [0, 1] measured from the node along the segment (thesis eqs A.42-A.47 in one step,
// ERRATA),
//   int f_i G_ij dl = int_0^1 F_i(tau) [G_ij + delta_ij ln tau] dtau - delta_ij int_0^1 F_i ln tau dtau,
// F = f dl/dtau: the first integrand is smooth (G + ln tau = -ln(r/tau) + xh xh / r^2 plus the
// regular wall images) and takes Gauss-Legendre; the second takes the Gauss rule for the
// weight -ln tau.
//
// Double layer  DL_j(x0) = PV int_C u_i(x) T_ijk(x, x0) n_k(x) dl(x), u given at the nodes and
// splined along the contour (ContourField2D). In 2D the kernel is bounded on a smooth
// contour (T_ijk n_k -> -2 kappa t_i t_j as x -> x0, n outward), so Gauss-Legendre applies as
// it stands (DoubleLayerForm::Direct). The solver uses the subtracted form: with n outward,
// PV int_C T_ijk n_k dl = -2 pi delta_ij at a smooth point of C (-4 pi inside, 0 outside;
// the wall images lie outside C and add nothing), so
//   DL_j(x0) = int_C [u_i(x) - u_i(x0)] T_ijk n_k dl - 2 pi u_j(x0),
// whose integrand vanishes at the pole.
//
// Near-singular subdivision (ContourDiscretisation2D): a piece of a segment closer than
// `nearSingularDistance` of its lengths to x0 or to an image of x0 (below the wall) is
// bisected, up to `nearSingularLevels` times; pieces touching the pole are judged by the
// images only (their singularity is treated exactly).
#include <capsula/operators/ContourDiscretisation2D.hpp>
#include <capsula/operators/ContourQuadrature2D.hpp>
#include <capsula/operators/DoubleLayerForm.hpp>

#include <capsula/contour/Contour.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/greens/FreeSpace2D.hpp>
#include <capsula/greens/Wall2D.hpp>
#include <capsula/quadrature/GaussLegendre.hpp>
#include <capsula/quadrature/LogWeightedGauss.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace capsula::operators {

/// Points outside the fluid where a 2D kernel is singular besides the pole: none in free
/// space; the mirror image of the pole below the wall y = 0.
template <class Kernel>
struct KernelImages2D {
  static constexpr int count = 0;
  static void images(const double* /*x0*/, double (*/*image*/)[2]) {}
  static bool inFluid(const double* /*x0*/) { return true; }
};

template <>
struct KernelImages2D<greens::Wall2D> {
  static constexpr int count = 1;
  static void images(const double* x0, double (*image)[2])
  {
    image[0][0] = x0[0];
    image[0][1] = -x0[1];
  }
  static bool inFluid(const double* x0) { return x0[greens::wallNormalAxis] > 0.0; }
};

/// u_j += G_ij(x, x0) f_i (the velocity at x0 of the force f at x, by reciprocity).
template <class Kernel>
inline void addSingleLayerTerm2D(const double x[2], const double x0[2], const double f[2], double u[2])
{
  double G[2][2];
  Kernel::stokeslet(x, x0, G);
  u[0] += G[0][0] * f[0] + G[1][0] * f[1];
  u[1] += G[0][1] * f[0] + G[1][1] * f[1];
}

/// W_ij = T_ijk(x, x0) a_k with a = n dl: the double-layer weight of one point.
template <class Kernel>
inline void doubleLayerWeight2D(const double x[2], const double x0[2], const double a[2], double W[4])
{
  double T[2][2][2];
  Kernel::stresslet(x, x0, T);
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      W[2 * i + j] = T[i][j][0] * a[0] + T[i][j][1] * a[1];
    }
  }
}

/// A piece [ta, tb] of a segment and whether the pole is its start or its end.
struct SegmentPiece2D {
  double ta = 0.0;
  double tb = 1.0;
  bool poleAtStart = false;
  bool poleAtEnd = false;
};

template <class Kernel>
class LayerPotentials2D {
public:
  explicit LayerPotentials2D(ContourDiscretisation2D parameters);

  const ContourDiscretisation2D& parameters() const { return parameters_; }

  /// Takes the geometry of `contour` (copied) and the node targets
  /// [firstTarget, firstTarget + numTargets) (the rows this rank owns). Throws
  /// core::InputError if a node lies outside the kernel's fluid (below the wall).
  void update(const contour::Contour& contour, int firstTarget, int numTargets);

  const contour::Contour& contour() const { return *contour_; }
  const ContourQuadrature2D& quadrature() const { return *quadrature_; }
  int firstTarget() const { return firstTarget_; }
  int numTargets() const { return numTargets_; }

  /// result[2 t + j] = int f_i G_ij(x, x_t) dl at the target nodes. `density(point,
  /// segment, t)` returns f (an Eigen::Vector2d) at the contour point (segment, t).
  template <class Density>
  void singleLayerAtNodes(const Density& density, double* result) const;

  /// result[2 t + j] = PV int u_i T_ijk(x, x_t) n_k dl at the target nodes, for u given at
  /// every node (2 per node). The point weights are built on the first call after update()
  /// and reused (the GMRES iterations apply this repeatedly on one geometry).
  void doubleLayerAtNodes(const double* nodalDensity, DoubleLayerForm form, double* result);

  /// The same at n points off the contour (2 per point) and for a density at any point.
  template <class Density>
  void singleLayerAtPoints(const double* points, int n, const Density& density, double* result) const;
  void doubleLayerAtPoints(const double* points, int n, const double* nodalDensity, double* result) const;

  /// Segment pieces that were bisected at the node targets in the last single- or
  /// double-layer build (diagnostics).
  long long subdividedSegments() const { return subdivided_; }

private:
  struct Extra {
    int segment;
    double t;
    double W[4];
  };

  // Pieces of segment k for a pole x0 (images `image`); whole segment when far.
  void pieces(int k, const double* x0, bool poleAtStart, bool poleAtEnd,
              std::vector<SegmentPiece2D>& out) const;
  void bisect(int k, const double* x0, const double (*image)[2], int numImages, SegmentPiece2D piece,
              int level, std::vector<SegmentPiece2D>& out) const;
  bool isNear(int k, const double* x0, const double (*image)[2], int numImages,
              const SegmentPiece2D& piece) const;
  void buildDoubleLayerWeights();

  ContourDiscretisation2D parameters_;
  quadrature::Rule1D gauss_;
  quadrature::Rule1D logRule_;
  std::optional<contour::Contour> contour_;
  std::optional<ContourQuadrature2D> quadrature_;
  std::vector<double> nodes_;      // 2 per node
  std::vector<double> midpoints_;  // 2 per segment: the spline at t = 1/2
  int firstTarget_ = 0;
  int numTargets_ = 0;

  bool hasDoubleWeights_ = false;
  std::vector<double> weights_;            // [(t * numPoints + p) * 4 + 2 i + j]
  std::vector<std::vector<Extra>> extras_; // per target: subdivided pieces' points
  mutable long long subdivided_ = 0;
};

// ---------------------------------------------------------------------------------------
// Implementation

template <class Kernel>
LayerPotentials2D<Kernel>::LayerPotentials2D(ContourDiscretisation2D parameters)
    : parameters_(parameters),
      gauss_(quadrature::gaussLegendre(parameters.gaussLegendrePoints)),
      logRule_(quadrature::logWeightedGauss(parameters.logWeightedPoints))
{
  validate(parameters_);
}

template <class Kernel>
void LayerPotentials2D<Kernel>::update(const contour::Contour& contour, int firstTarget, int numTargets)
{
  const int n = contour.numberOfNodes();
  core::require<core::InputError>(firstTarget >= 0 && numTargets >= 0 && firstTarget + numTargets <= n,
                                  "The target nodes [", firstTarget, ", ", firstTarget + numTargets,
                                  ") are not nodes of the ", n, "-node contour.");
  for (int i = 0; i < n; ++i) {
    const double x[2] = {contour.nodes()(0, i), contour.nodes()(1, i)};
    core::require<core::InputError>(KernelImages2D<Kernel>::inFluid(x), "Node ", i, " of the contour at (",
                                    x[0], ", ", x[1], ") lies outside the fluid of the ", Kernel::name,
                                    " kernel: the cell has touched the wall.");
  }
  contour_.emplace(contour);
  quadrature_.emplace(contour, gauss_);
  nodes_.resize(2 * static_cast<std::size_t>(n));
  midpoints_.resize(2 * static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    nodes_[2 * i] = contour.nodes()(0, i);
    nodes_[2 * i + 1] = contour.nodes()(1, i);
    const Eigen::Vector2d mid = contour.pointAt(i, 0.5).position;
    midpoints_[2 * i] = mid.x();
    midpoints_[2 * i + 1] = mid.y();
  }
  firstTarget_ = firstTarget;
  numTargets_ = numTargets;
  hasDoubleWeights_ = false;
  weights_.clear();
  extras_.clear();
}

template <class Kernel>
bool LayerPotentials2D<Kernel>::isNear(int k, const double* x0, const double (*image)[2], int numImages,
                                       const SegmentPiece2D& piece) const
{
  const int n = contour_->numberOfNodes();
  // The piece's ends and middle: cached for the whole segment, evaluated for sub-pieces.
  double a[2], b[2], m[2];
  if (piece.ta == 0.0 && piece.tb == 1.0) {
    a[0] = nodes_[2 * k];
    a[1] = nodes_[2 * k + 1];
    b[0] = nodes_[2 * ((k + 1) % n)];
    b[1] = nodes_[2 * ((k + 1) % n) + 1];
    m[0] = midpoints_[2 * k];
    m[1] = midpoints_[2 * k + 1];
  } else {
    const Eigen::Vector2d pa = contour_->pointAt(k, piece.ta).position;
    const Eigen::Vector2d pb = contour_->pointAt(k, piece.tb).position;
    const Eigen::Vector2d pm = contour_->pointAt(k, 0.5 * (piece.ta + piece.tb)).position;
    a[0] = pa.x(), a[1] = pa.y(), b[0] = pb.x(), b[1] = pb.y(), m[0] = pm.x(), m[1] = pm.y();
  }
  const double length = std::hypot(m[0] - a[0], m[1] - a[1]) + std::hypot(b[0] - m[0], b[1] - m[1]);
  const double reach = parameters_.nearSingularDistance * length;
  const auto within = [&](const double* p) {
    return std::min({std::hypot(p[0] - a[0], p[1] - a[1]), std::hypot(p[0] - m[0], p[1] - m[1]),
                     std::hypot(p[0] - b[0], p[1] - b[1])}) < reach;
  };
  if (!piece.poleAtStart && !piece.poleAtEnd && within(x0)) {
    return true;
  }
  for (int q = 0; q < numImages; ++q) {
    if (within(image[q])) {
      return true;
    }
  }
  return false;
}

template <class Kernel>
void LayerPotentials2D<Kernel>::bisect(int k, const double* x0, const double (*image)[2], int numImages,
                                       SegmentPiece2D piece, int level,
                                       std::vector<SegmentPiece2D>& out) const
{
  if (level >= parameters_.nearSingularLevels || !isNear(k, x0, image, numImages, piece)) {
    out.push_back(piece);
    return;
  }
  const double middle = 0.5 * (piece.ta + piece.tb);
  bisect(k, x0, image, numImages, {piece.ta, middle, piece.poleAtStart, false}, level + 1, out);
  bisect(k, x0, image, numImages, {middle, piece.tb, false, piece.poleAtEnd}, level + 1, out);
}

template <class Kernel>
void LayerPotentials2D<Kernel>::pieces(int k, const double* x0, bool poleAtStart, bool poleAtEnd,
                                       std::vector<SegmentPiece2D>& out) const
{
  out.clear();
  const SegmentPiece2D whole{0.0, 1.0, poleAtStart, poleAtEnd};
  if (!(parameters_.nearSingularDistance > 0.0)) {
    out.push_back(whole);
    return;
  }
  double image[KernelImages2D<Kernel>::count + 1][2];
  KernelImages2D<Kernel>::images(x0, image);
  bisect(k, x0, image, KernelImages2D<Kernel>::count, whole, 0, out);
}

namespace detail2d {

/// Calls visit(point, t, dl) at the Gauss points of piece [ta, tb] of segment k.
template <class Visit>
inline void visitGaussPiece(const contour::Contour& contour, const quadrature::Rule1D& rule, int k,
                            double ta, double tb, Visit&& visit)
{
  const std::vector<double>& s = contour.parameters();
  const double span = (s[static_cast<std::size_t>(k) + 1] - s[static_cast<std::size_t>(k)]) * (tb - ta);
  for (std::size_t q = 0; q < rule.points.size(); ++q) {
    const double t = ta + rule.points[q] * (tb - ta);
    const contour::ContourPoint point = contour.pointAt(k, t);
    visit(point, t, rule.weights[q] * span * point.metric);
  }
}

} // namespace detail2d

template <class Kernel>
template <class Density>
void LayerPotentials2D<Kernel>::singleLayerAtNodes(const Density& density, double* result) const
{
  const contour::Contour& c = *contour_;
  const ContourQuadrature2D& quad = *quadrature_;
  const int n = c.numberOfNodes();
  const int perSegment = quad.pointsPerSegment();
  const std::vector<double>& s = c.parameters();

  // f dl at the regular points, once for all targets.
  std::vector<double> load(2 * static_cast<std::size_t>(quad.numberOfPoints()));
  for (int p = 0; p < quad.numberOfPoints(); ++p) {
    const Eigen::Vector2d f = density(quad.point(p), quad.segmentOf(p), quad.parameterOf(p));
    load[2 * p] = f.x() * quad.weights()[p];
    load[2 * p + 1] = f.y() * quad.weights()[p];
  }
  const double* xq = quad.positions().data();

  std::vector<SegmentPiece2D> split;
  long long subdivided = 0;
  for (int t = 0; t < numTargets_; ++t) {
    const int m = firstTarget_ + t;
    const double x0[2] = {nodes_[2 * m], nodes_[2 * m + 1]};
    double u[2] = {0.0, 0.0};
    for (int k = 0; k < n; ++k) {
      const bool poleAtStart = k == m;
      const bool poleAtEnd = (k + 1) % n == m;
      pieces(k, x0, poleAtStart, poleAtEnd, split);
      if (split.size() == 1 && !poleAtStart && !poleAtEnd) {
        for (int p = k * perSegment; p < (k + 1) * perSegment; ++p) {
          addSingleLayerTerm2D<Kernel>(xq + 2 * p, x0, &load[2 * p], u);
        }
        continue;
      }
      subdivided += split.size() > 1 ? 1 : 0;
      const double segmentSpan = s[static_cast<std::size_t>(k) + 1] - s[static_cast<std::size_t>(k)];
      for (const SegmentPiece2D& piece : split) {
        if (!piece.poleAtStart && !piece.poleAtEnd) {
          detail2d::visitGaussPiece(c, gauss_, k, piece.ta, piece.tb,
                                    [&](const contour::ContourPoint& point, double tp, double dl) {
                                      const Eigen::Vector2d f = density(point, k, tp) * dl;
                                      const double fx[2] = {f.x(), f.y()};
                                      const double x[2] = {point.position.x(), point.position.y()};
                                      addSingleLayerTerm2D<Kernel>(x, x0, fx, u);
                                    });
          continue;
        }
        // tau from the pole: t = ta + tau (tb - ta) or t = tb - tau (tb - ta).
        const double width = piece.tb - piece.ta;
        const auto parameterAt = [&](double tau) {
          return piece.poleAtStart ? piece.ta + tau * width : piece.tb - tau * width;
        };
        const double jacobian = segmentSpan * width; // ds / dtau
        for (std::size_t q = 0; q < gauss_.points.size(); ++q) {
          const double tau = gauss_.points[q];
          const double tp = parameterAt(tau);
          const contour::ContourPoint point = c.pointAt(k, tp);
          const Eigen::Vector2d f = density(point, k, tp) * (gauss_.weights[q] * jacobian * point.metric);
          const double x[2] = {point.position.x(), point.position.y()};
          double G[2][2];
          Kernel::stokeslet(x, x0, G);
          const double logTau = std::log(tau);
          G[0][0] += logTau;
          G[1][1] += logTau;
          u[0] += G[0][0] * f.x() + G[1][0] * f.y();
          u[1] += G[0][1] * f.x() + G[1][1] * f.y();
        }
        for (std::size_t q = 0; q < logRule_.points.size(); ++q) {
          const double tp = parameterAt(logRule_.points[q]);
          const contour::ContourPoint point = c.pointAt(k, tp);
          const Eigen::Vector2d f = density(point, k, tp) * (logRule_.weights[q] * jacobian * point.metric);
          u[0] += f.x();
          u[1] += f.y();
        }
      }
    }
    result[2 * t] = u[0];
    result[2 * t + 1] = u[1];
  }
  subdivided_ = subdivided;
}

template <class Kernel>
void LayerPotentials2D<Kernel>::buildDoubleLayerWeights()
{
  const contour::Contour& c = *contour_;
  const ContourQuadrature2D& quad = *quadrature_;
  const int n = c.numberOfNodes();
  const int numPoints = quad.numberOfPoints();
  const int perSegment = quad.pointsPerSegment();
  const double* xq = quad.positions().data();
  const double* nq = quad.normals().data();
  const double* wq = quad.weights().data();

  weights_.assign(static_cast<std::size_t>(numTargets_) * numPoints * 4, 0.0);
  extras_.assign(static_cast<std::size_t>(numTargets_), {});
  std::vector<SegmentPiece2D> split;
  long long subdivided = 0;
  for (int t = 0; t < numTargets_; ++t) {
    const int m = firstTarget_ + t;
    const double x0[2] = {nodes_[2 * m], nodes_[2 * m + 1]};
    double* row = &weights_[static_cast<std::size_t>(t) * numPoints * 4];
    for (int k = 0; k < n; ++k) {
      pieces(k, x0, k == m, (k + 1) % n == m, split);
      if (split.size() == 1) {
        for (int p = k * perSegment; p < (k + 1) * perSegment; ++p) {
          const double a[2] = {nq[2 * p] * wq[p], nq[2 * p + 1] * wq[p]};
          doubleLayerWeight2D<Kernel>(xq + 2 * p, x0, a, row + 4 * p);
        }
        continue;
      }
      ++subdivided;
      for (const SegmentPiece2D& piece : split) {
        detail2d::visitGaussPiece(c, gauss_, k, piece.ta, piece.tb,
                                  [&](const contour::ContourPoint& point, double tp, double dl) {
                                    Extra extra{k, tp, {}};
                                    const double x[2] = {point.position.x(), point.position.y()};
                                    const double a[2] = {point.normal.x() * dl, point.normal.y() * dl};
                                    doubleLayerWeight2D<Kernel>(x, x0, a, extra.W);
                                    extras_[static_cast<std::size_t>(t)].push_back(extra);
                                  });
      }
    }
  }
  subdivided_ = subdivided;
  hasDoubleWeights_ = true;
}

template <class Kernel>
void LayerPotentials2D<Kernel>::doubleLayerAtNodes(const double* nodalDensity, DoubleLayerForm form,
                                                   double* result)
{
  if (!hasDoubleWeights_) {
    buildDoubleLayerWeights();
  }
  const ContourQuadrature2D& quad = *quadrature_;
  const int numPoints = quad.numberOfPoints();
  const ContourField2D field(*contour_, nodalDensity);
  std::vector<double> u(2 * static_cast<std::size_t>(numPoints));
  for (int p = 0; p < numPoints; ++p) {
    const Eigen::Vector2d v = field.at(quad.segmentOf(p), quad.parameterOf(p));
    u[2 * p] = v.x();
    u[2 * p + 1] = v.y();
  }
  const bool subtract = form == DoubleLayerForm::Subtracted;
  for (int t = 0; t < numTargets_; ++t) {
    const int m = firstTarget_ + t;
    const double u0[2] = {subtract ? nodalDensity[2 * m] : 0.0, subtract ? nodalDensity[2 * m + 1] : 0.0};
    const double* row = &weights_[static_cast<std::size_t>(t) * numPoints * 4];
    double sum[2] = {0.0, 0.0};
    for (int p = 0; p < numPoints; ++p) {
      const double v0 = u[2 * p] - u0[0];
      const double v1 = u[2 * p + 1] - u0[1];
      sum[0] += v0 * row[4 * p] + v1 * row[4 * p + 2];
      sum[1] += v0 * row[4 * p + 1] + v1 * row[4 * p + 3];
    }
    for (const Extra& extra : extras_[static_cast<std::size_t>(t)]) {
      const Eigen::Vector2d v = field.at(extra.segment, extra.t);
      const double v0 = v.x() - u0[0];
      const double v1 = v.y() - u0[1];
      sum[0] += v0 * extra.W[0] + v1 * extra.W[2];
      sum[1] += v0 * extra.W[1] + v1 * extra.W[3];
    }
    if (subtract) {
      sum[0] -= 2.0 * M_PI * u0[0];
      sum[1] -= 2.0 * M_PI * u0[1];
    }
    result[2 * t] = sum[0];
    result[2 * t + 1] = sum[1];
  }
}

template <class Kernel>
template <class Density>
void LayerPotentials2D<Kernel>::singleLayerAtPoints(const double* points, int numberOfPoints,
                                                    const Density& density, double* result) const
{
  const contour::Contour& c = *contour_;
  std::vector<SegmentPiece2D> split;
  for (int i = 0; i < numberOfPoints; ++i) {
    const double* x0 = points + 2 * i;
    double u[2] = {0.0, 0.0};
    for (int k = 0; k < c.numberOfSegments(); ++k) {
      pieces(k, x0, false, false, split);
      for (const SegmentPiece2D& piece : split) {
        detail2d::visitGaussPiece(c, gauss_, k, piece.ta, piece.tb,
                                  [&](const contour::ContourPoint& point, double tp, double dl) {
                                    const Eigen::Vector2d f = density(point, k, tp) * dl;
                                    const double fx[2] = {f.x(), f.y()};
                                    const double x[2] = {point.position.x(), point.position.y()};
                                    addSingleLayerTerm2D<Kernel>(x, x0, fx, u);
                                  });
      }
    }
    result[2 * i] = u[0];
    result[2 * i + 1] = u[1];
  }
}

template <class Kernel>
void LayerPotentials2D<Kernel>::doubleLayerAtPoints(const double* points, int numberOfPoints,
                                                    const double* nodalDensity, double* result) const
{
  const contour::Contour& c = *contour_;
  const ContourField2D field(c, nodalDensity);
  std::vector<SegmentPiece2D> split;
  for (int i = 0; i < numberOfPoints; ++i) {
    const double* x0 = points + 2 * i;
    double sum[2] = {0.0, 0.0};
    for (int k = 0; k < c.numberOfSegments(); ++k) {
      pieces(k, x0, false, false, split);
      for (const SegmentPiece2D& piece : split) {
        detail2d::visitGaussPiece(c, gauss_, k, piece.ta, piece.tb,
                                  [&](const contour::ContourPoint& point, double tp, double dl) {
                                    const Eigen::Vector2d v = field.at(k, tp);
                                    const double x[2] = {point.position.x(), point.position.y()};
                                    const double a[2] = {point.normal.x() * dl, point.normal.y() * dl};
                                    double W[4];
                                    doubleLayerWeight2D<Kernel>(x, x0, a, W);
                                    sum[0] += v.x() * W[0] + v.y() * W[2];
                                    sum[1] += v.x() * W[1] + v.y() * W[3];
                                  });
      }
    }
    result[2 * i] = sum[0];
    result[2 * i + 1] = sum[1];
  }
}

} // namespace capsula::operators
