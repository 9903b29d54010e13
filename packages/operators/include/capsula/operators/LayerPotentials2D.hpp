#pragma once
// (Length: one class template per Green's function, instantiated in InterfaceVelocity2D.cpp;
// its geometry cache, pair classification and the layer sums share the members that the
// hot loops inline across, so they stay in one header.)
//
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
//
// Cost (singleLayerAtNodes, the lambda = 1 right-hand side): update() decides once per
// geometry which (target, segment) pairs need the singular or near-singular rules, by
// squared distances to each segment's ends and middle, vectorised over the targets; the
// other pairs (all but ~6 per target) are summed by RegularSums2D's vectorised loop over
// flat arrays. The bisected pieces are cached per geometry (their ends and middle) and per
// density (their Gauss points' f dl), so neighbouring targets that bisect the same segment
// share the work; the Gauss points of these special pairs are then gathered and evaluated
// by the same vectorised pair formula. singleLayerAtNodesReference() is the plain per-pair
// evaluation of the same rules, kept as the reference of the fast path (tests/unit/operators).
// The caches make the const evaluations unsafe to call concurrently on one object.
#include <capsula/operators/ContourDiscretisation2D.hpp>
#include <capsula/operators/ContourQuadrature2D.hpp>
#include <capsula/operators/DoubleLayerForm.hpp>
#include <capsula/operators/RegularSums2D.hpp>
#include <capsula/operators/SplineDoubleLayer2D.hpp>

#include <capsula/contour/Contour.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/core/Timers.hpp>
#include <capsula/greens/FreeSpace2D.hpp>
#include <capsula/greens/Wall2D.hpp>
#include <capsula/quadrature/GaussLegendre.hpp>
#include <capsula/quadrature/LogWeightedGauss.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

namespace capsula::operators {

/// Points outside the fluid where a 2D kernel is singular besides the pole: none in free
/// space; the mirror image of the pole below the wall y = 0.
template <class Kernel>
struct KernelImages2D {
  static constexpr int count = 0;
  static void images(const double* /*x0*/, double (* /*image*/)[2]) {}
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

/// The vectorised sums of a kernel (RegularSums2D.hpp): all regular pairs, or a list of pairs.
template <class Kernel>
struct RegularSums2DOf;

template <>
struct RegularSums2DOf<greens::Wall2D> {
  static void addSums(const double* px, const double* py, const double* fx, const double* fy, int perSegment,
                      int segments, const double* tx, const double* ty, int paddedTargets, const double* mask,
                      double* ux, double* uy)
  {
    addWallStokesletSums2D(px, py, fx, fy, perSegment, segments, tx, ty, paddedTargets, mask, ux, uy);
  }
  static void pairs(const double* x, const double* y, const double* fx, const double* fy, const double* x0,
                    const double* y0, int count, double* ux, double* uy)
  {
    wallStokesletPairs2D(x, y, fx, fy, x0, y0, count, ux, uy);
  }
  static void doubleLayerWeight(double x, double y, double a0, double a1, double x0, double y0, double W[4])
  {
    wallDoubleLayerWeight2D(x, y, a0, a1, x0, y0, W);
  }
  static void addDoubleLayerCoefficients(const double* px, const double* py, const double* ax, const double* ay,
                                         const double* basis, int perSegment, int segments, const double* tx,
                                         const double* ty, const double* mask, SplineDoubleLayer2D& layer)
  {
    addWallDoubleLayerCoefficients2D(px, py, ax, ay, basis, perSegment, segments, tx, ty, mask, layer);
  }
};

template <>
struct RegularSums2DOf<greens::FreeSpace2D> {
  static void addSums(const double* px, const double* py, const double* fx, const double* fy, int perSegment,
                      int segments, const double* tx, const double* ty, int paddedTargets, const double* mask,
                      double* ux, double* uy)
  {
    addFreeSpaceStokesletSums2D(px, py, fx, fy, perSegment, segments, tx, ty, paddedTargets, mask, ux, uy);
  }
  static void pairs(const double* x, const double* y, const double* fx, const double* fy, const double* x0,
                    const double* y0, int count, double* ux, double* uy)
  {
    freeSpaceStokesletPairs2D(x, y, fx, fy, x0, y0, count, ux, uy);
  }
  static void doubleLayerWeight(double x, double y, double a0, double a1, double x0, double y0, double W[4])
  {
    freeSpaceDoubleLayerWeight2D(x, y, a0, a1, x0, y0, W);
  }
  static void addDoubleLayerCoefficients(const double* px, const double* py, const double* ax, const double* ay,
                                         const double* basis, int perSegment, int segments, const double* tx,
                                         const double* ty, const double* mask, SplineDoubleLayer2D& layer)
  {
    addFreeSpaceDoubleLayerCoefficients2D(px, py, ax, ay, basis, perSegment, segments, tx, ty, mask, layer);
  }
};

/// A piece [ta, tb] of a segment, the index-th of its 2^level equal parts (the bisections
/// are dyadic), and whether the pole is its start or its end.
struct SegmentPiece2D {
  double ta = 0.0;
  double tb = 1.0;
  bool poleAtStart = false;
  bool poleAtEnd = false;
  int level = 0;
  int index = 0;
  int slot = -1; ///< where LayerPotentials2D caches its geometry (bisected pieces)
};

template <class Kernel>
class LayerPotentials2D {
  static_assert(KernelImages2D<Kernel>::count <= 1, "the pair classification handles at most one image");

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

  /// The same rules evaluated pair by pair, without the vectorised sums or the piece cache:
  /// the reference that singleLayerAtNodes must reproduce to round-off (tests).
  template <class Density>
  void singleLayerAtNodesReference(const Density& density, double* result) const;

  /// result[2 t + j] = PV int u_i T_ijk(x, x_t) n_k dl at the target nodes, for u given at
  /// every node (2 per node). The map from the density's spline data to these values
  /// (SplineDoubleLayer2D) is built on the first call after update() and reused (the GMRES
  /// iterations apply this repeatedly on one geometry).
  void doubleLayerAtNodes(const double* nodalDensity, DoubleLayerForm form, double* result);

  /// The same at n points off the contour (2 per point) and for a density at any point.
  template <class Density>
  void singleLayerAtPoints(const double* points, int n, const Density& density, double* result) const;
  void doubleLayerAtPoints(const double* points, int n, const double* nodalDensity, double* result) const;

  /// Segment pieces that were bisected at the node targets in the last single- or
  /// double-layer build (diagnostics).
  long long subdividedSegments() const { return subdivided_; }

private:
  /// A piece's ends, middle and (near-singular distance x its length)^2, for one geometry;
  /// its Gauss points (x, y, dl, f_x dl, f_y dl) in pieceGauss_ once a single layer uses it.
  struct CachedPiece {
    double a[2];
    double m[2];
    double b[2];
    double reach2;
    double ta;
    double tb;
    int gauss = -1;           // index of its first Gauss point in pieceGauss_ (-1: none yet)
    unsigned densityCall = 0; // the single-layer call whose f dl pieceGauss_ holds
  };
  static constexpr int gaussStride = 5;

  // Pieces of segment k for a pole x0 (images `image`); whole segment when far.
  void pieces(int k, const double* x0, bool poleAtStart, bool poleAtEnd, std::vector<SegmentPiece2D>& out) const;
  void bisect(int k, const double* x0, const double (*image)[2], int numImages, SegmentPiece2D piece, int level,
              std::vector<SegmentPiece2D>& out) const;
  bool isNear(const double* x0, const double (*image)[2], int numImages, const SegmentPiece2D& piece) const;
  // |m - a| + |b - m|: the length that scales the reach (sqrt of squares: std::hypot's
  // overflow care is not needed for O(1) coordinates and cost 2% of the right-hand side).
  static double pieceLength(const CachedPiece& piece)
  {
    const double ma[2] = {piece.m[0] - piece.a[0], piece.m[1] - piece.a[1]};
    const double bm[2] = {piece.b[0] - piece.m[0], piece.b[1] - piece.m[1]};
    return std::sqrt(ma[0] * ma[0] + ma[1] * ma[1]) + std::sqrt(bm[0] * bm[0] + bm[1] * bm[1]);
  }
  // pieceCache_ index of the index-th of the 2^level parts of segment k (made on first use).
  int cachedPiece(int k, int level, int index) const;
  // The Gauss points of a bisected piece with f dl of `density` (gaussStride per point).
  template <class Density>
  const double* pieceGauss(int k, const SegmentPiece2D& piece, const Density& density) const;
  // regularMask_ and the special pairs of every target.
  void classifyPairs();
  void buildDoubleLayerWeights();

  ContourDiscretisation2D parameters_;
  quadrature::Rule1D gauss_;
  quadrature::Rule1D logRule_;
  std::vector<int> mirror_;      // gauss_.points[mirror_[q]] = 1 - gauss_.points[q]
  std::vector<double> logGauss_; // ln gauss_.points[q]
  std::optional<contour::Contour> contour_;
  std::optional<ContourQuadrature2D> quadrature_;
  std::vector<double> nodes_;     // 2 per node
  std::vector<double> midpoints_; // 2 per segment: the spline at t = 1/2
  int firstTarget_ = 0;
  int numTargets_ = 0;

  // Flat copies for the regular sums: quadrature points, targets (padded to the vector
  // width with copies of the last one), mask[k * paddedTargets_ + t] (1: regular pair).
  std::vector<double> pointX_, pointY_;
  std::vector<double> targetX_, targetY_;
  int paddedTargets_ = 0;
  std::vector<double> regularMask_;
  std::vector<int> specialStart_;    // target t's special segments:
  std::vector<int> specialSegments_; // specialSegments_[specialStart_[t] .. specialStart_[t + 1])
  std::vector<int> specialFill_;
  std::vector<double> segmentEnds_; // a, m, b of every whole segment (6 per segment)
  std::vector<double> segmentReach2_;
  mutable std::vector<double> loadX_, loadY_, sumX_, sumY_;
  // The Gauss points of the special pairs, gathered for one vectorised evaluation: point,
  // f dl, target, and the result; pairStart_[t] is target t's first.
  mutable std::vector<double> pairX_, pairY_, pairFx_, pairFy_, pairX0_, pairY0_, pairUx_, pairUy_;
  mutable std::vector<int> pairStart_;
  mutable std::vector<double> specialU_; // 2 per target: the ln tau terms
  mutable std::vector<SegmentPiece2D> split_;

  // Pieces of the current geometry: whole segments at [0, n), bisected ones after them.
  mutable std::vector<CachedPiece> pieceCache_;
  static constexpr int treeLevels = 5;
  static constexpr std::size_t treeSize = std::size_t{2} << treeLevels; // slots 1 .. 2^(levels+1) - 1
  mutable std::vector<int> pieceTree_;                                  // -1: not cached
  mutable std::unordered_map<std::uint64_t, int> pieceIndex_;
  mutable std::vector<double> pieceGauss_;
  mutable unsigned densityCall_ = 0;

  bool hasDoubleWeights_ = false;
  SplineDoubleLayer2D doubleLayer_;
  mutable long long subdivided_ = 0;

  Teuchos::RCP<Teuchos::Time> geometryTimer_;
  Teuchos::RCP<Teuchos::Time> loadTimer_;
  Teuchos::RCP<Teuchos::Time> regularTimer_;
  Teuchos::RCP<Teuchos::Time> specialTimer_;
  Teuchos::RCP<Teuchos::Time> doubleWeightsTimer_;
  Teuchos::RCP<Teuchos::Time> doubleApplyTimer_;
};

// ---------------------------------------------------------------------------------------
// Implementation

template <class Kernel>
LayerPotentials2D<Kernel>::LayerPotentials2D(ContourDiscretisation2D parameters)
    : parameters_(parameters),
      gauss_(quadrature::gaussLegendre(parameters.gaussLegendrePoints)),
      logRule_(quadrature::logWeightedGauss(parameters.logWeightedPoints)),
      geometryTimer_(core::timer("2D layers: geometry and pair classification")),
      loadTimer_(core::timer("2D single layer: load at the Gauss points")),
      regularTimer_(core::timer("2D single layer: regular sums")),
      specialTimer_(core::timer("2D single layer: singular and near-singular pairs")),
      doubleWeightsTimer_(core::timer("2D double layer: spline coefficients")),
      doubleApplyTimer_(core::timer("2D double layer: apply"))
{
  validate(parameters_);
  const int q = static_cast<int>(gauss_.points.size());
  for (int i = 0; i < q; ++i) {
    // Gauss-Legendre points are symmetric about 1/2: the mirror of each is another.
    int best = 0;
    for (int j = 1; j < q; ++j) {
      if (std::abs(gauss_.points[j] - (1.0 - gauss_.points[i])) <
          std::abs(gauss_.points[best] - (1.0 - gauss_.points[i]))) {
        best = j;
      }
    }
    core::require(std::abs(gauss_.points[best] - (1.0 - gauss_.points[i])) < 1e-14,
                  "LayerPotentials2D: the Gauss-Legendre rule is not symmetric on [0, 1].");
    mirror_.push_back(best);
    logGauss_.push_back(std::log(gauss_.points[i]));
  }
}

template <class Kernel>
void LayerPotentials2D<Kernel>::update(const contour::Contour& contour, int firstTarget, int numTargets)
{
  Teuchos::TimeMonitor guard(*geometryTimer_);
  const int n = contour.numberOfNodes();
  core::require<core::InputError>(firstTarget >= 0 && numTargets >= 0 && firstTarget + numTargets <= n,
                                  "The target nodes [", firstTarget, ", ", firstTarget + numTargets,
                                  ") are not nodes of the ", n, "-node contour.");
  for (int i = 0; i < n; ++i) {
    const double x[2] = {contour.nodes()(0, i), contour.nodes()(1, i)};
    core::require<core::InputError>(KernelImages2D<Kernel>::inFluid(x), "Node ", i, " of the contour at (", x[0], ", ",
                                    x[1], ") lies outside the fluid of the ", Kernel::name,
                                    " kernel: the cell has touched the wall.");
  }
  contour_.emplace(contour);
  quadrature_.emplace(contour, gauss_);
  nodes_.resize(2 * static_cast<std::size_t>(n));
  midpoints_.resize(2 * static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    nodes_[2 * i] = contour.nodes()(0, i);
    nodes_[2 * i + 1] = contour.nodes()(1, i);
    const Eigen::Vector2d mid = contour.positionAt(i, 0.5);
    midpoints_[2 * i] = mid.x();
    midpoints_[2 * i + 1] = mid.y();
  }
  firstTarget_ = firstTarget;
  numTargets_ = numTargets;
  hasDoubleWeights_ = false;

  // The whole segments: ends, middle and reach (the piece test of isNear()).
  pieceCache_.resize(static_cast<std::size_t>(n));
  pieceIndex_.clear();
  pieceTree_.assign(static_cast<std::size_t>(n) * treeSize, -1);
  pieceGauss_.clear();
  for (int k = 0; k < n; ++k) {
    CachedPiece& piece = pieceCache_[static_cast<std::size_t>(k)];
    const int next = (k + 1) % n;
    piece.a[0] = nodes_[2 * k];
    piece.a[1] = nodes_[2 * k + 1];
    piece.b[0] = nodes_[2 * next];
    piece.b[1] = nodes_[2 * next + 1];
    piece.m[0] = midpoints_[2 * k];
    piece.m[1] = midpoints_[2 * k + 1];
    const double length = pieceLength(piece);
    const double reach = parameters_.nearSingularDistance * length;
    piece.reach2 = reach * reach;
    piece.ta = 0.0;
    piece.tb = 1.0;
    piece.gauss = -1;
    piece.densityCall = 0;
  }

  const int numPoints = quadrature_->numberOfPoints();
  pointX_.resize(static_cast<std::size_t>(numPoints));
  pointY_.resize(static_cast<std::size_t>(numPoints));
  for (int p = 0; p < numPoints; ++p) {
    pointX_[p] = quadrature_->positions()[2 * p];
    pointY_[p] = quadrature_->positions()[2 * p + 1];
  }
  classifyPairs();
}

template <class Kernel>
void LayerPotentials2D<Kernel>::classifyPairs()
{
  const int n = contour_->numberOfNodes();
  paddedTargets_ = (numTargets_ + targetLaneMultiple - 1) / targetLaneMultiple * targetLaneMultiple;
  const auto padded = static_cast<std::size_t>(paddedTargets_);
  targetX_.resize(padded);
  targetY_.resize(padded);
  for (int t = 0; t < paddedTargets_; ++t) {
    const int m = firstTarget_ + std::min(t, numTargets_ - 1);
    targetX_[t] = nodes_[2 * m];
    targetY_[t] = nodes_[2 * m + 1];
  }
  const bool bisecting = parameters_.nearSingularDistance > 0.0 && parameters_.nearSingularLevels > 0;
  if (bisecting) {
    regularMask_.resize(static_cast<std::size_t>(n) * padded); // markNearSegments2D writes every entry
  } else {
    regularMask_.assign(static_cast<std::size_t>(n) * padded, 1.0);
  }
  // Whole segments that pieces() would bisect: the test of isNear() with squared
  // distances (the same decision), for every target at once. With no bisection allowed
  // they stay regular pairs (pieces() returns the whole segment).
  if (bisecting) {
    segmentEnds_.resize(6 * static_cast<std::size_t>(n));
    segmentReach2_.resize(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
      const CachedPiece& piece = pieceCache_[static_cast<std::size_t>(k)];
      const double ends[6] = {piece.a[0], piece.a[1], piece.m[0], piece.m[1], piece.b[0], piece.b[1]};
      std::copy(ends, ends + 6, &segmentEnds_[6 * static_cast<std::size_t>(k)]);
      segmentReach2_[static_cast<std::size_t>(k)] = piece.reach2;
    }
    // The images are the mirror images below the wall (KernelImages2D<Wall2D>).
    markNearSegments2D(segmentEnds_.data(), segmentReach2_.data(), n, targetX_.data(), targetY_.data(), paddedTargets_,
                       KernelImages2D<Kernel>::count == 1, regularMask_.data());
  }
  // The two segments ending at the target take the log-singular rule.
  for (int t = 0; t < numTargets_; ++t) {
    const int m = firstTarget_ + t;
    regularMask_[static_cast<std::size_t>(m) * padded + t] = 0.0;
    regularMask_[static_cast<std::size_t>((m + n - 1) % n) * padded + t] = 0.0;
  }
  // Each target's special segments in increasing k (counted, then filled, row by row).
  // (Locals throughout: the loops over the mask then neither reload the members nor
  // branch when counting.)
  const int targets = numTargets_;
  specialStart_.assign(static_cast<std::size_t>(targets) + 1, 0);
  int* count = specialStart_.data() + 1;
  for (int k = 0; k < n; ++k) {
    const double* use = &regularMask_[static_cast<std::size_t>(k) * padded];
    for (int t = 0; t < targets; ++t) {
      count[t] += static_cast<int>(1.0 - use[t]);
    }
  }
  for (int t = 0; t < targets; ++t) {
    specialStart_[t + 1] += specialStart_[t];
  }
  specialSegments_.resize(static_cast<std::size_t>(specialStart_[targets]));
  specialFill_.assign(specialStart_.begin(), specialStart_.end() - 1);
  int* fill = specialFill_.data();
  int* special = specialSegments_.data();
  for (int k = 0; k < n; ++k) {
    const double* use = &regularMask_[static_cast<std::size_t>(k) * padded];
    for (int t = 0; t < targets; ++t) {
      if (use[t] == 0.0) {
        special[fill[t]++] = k;
      }
    }
  }
}

template <class Kernel>
int LayerPotentials2D<Kernel>::cachedPiece(int k, int level, int index) const
{
  if (level == 0) {
    return k;
  }
  // Levels up to treeLevels in a flat per-segment table (heap numbering), deeper ones in a
  // hash map: most bisections stop within a few levels.
  int* slot;
  if (level <= treeLevels) {
    slot = &pieceTree_[static_cast<std::size_t>(k) * treeSize + (1u << level) + static_cast<unsigned>(index)];
  } else {
    const std::uint64_t key = (static_cast<std::uint64_t>(k) << 32) | (static_cast<std::uint64_t>(level) << 24) |
                              static_cast<std::uint64_t>(index);
    slot = &pieceIndex_.try_emplace(key, -1).first->second;
  }
  if (*slot < 0) {
    *slot = static_cast<int>(pieceCache_.size());
    // The same points bisect() used to evaluate for every target: exact dyadic parameters.
    CachedPiece piece;
    piece.ta = std::ldexp(static_cast<double>(index), -level);
    piece.tb = std::ldexp(static_cast<double>(index + 1), -level);
    const Eigen::Vector2d pa = contour_->positionAt(k, piece.ta);
    const Eigen::Vector2d pb = contour_->positionAt(k, piece.tb);
    const Eigen::Vector2d pm = contour_->positionAt(k, 0.5 * (piece.ta + piece.tb));
    piece.a[0] = pa.x(), piece.a[1] = pa.y(), piece.b[0] = pb.x(), piece.b[1] = pb.y();
    piece.m[0] = pm.x(), piece.m[1] = pm.y();
    const double length = pieceLength(piece);
    const double reach = parameters_.nearSingularDistance * length;
    piece.reach2 = reach * reach;
    pieceCache_.push_back(piece);
  }
  return *slot;
}

template <class Kernel>
bool LayerPotentials2D<Kernel>::isNear(const double* x0, const double (*image)[2], int numImages,
                                       const SegmentPiece2D& piece) const
{
  // Nearer than the reach to the piece's ends or middle (squared: no square roots).
  const CachedPiece& c = pieceCache_[static_cast<std::size_t>(piece.slot)];
  const auto within = [&c](const double* p) {
    const auto d2 = [p](const double* q) { return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]); };
    return std::min({d2(c.a), d2(c.m), d2(c.b)}) < c.reach2;
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
                                       SegmentPiece2D piece, int level, std::vector<SegmentPiece2D>& out) const
{
  piece.slot = cachedPiece(k, piece.level, piece.index);
  if (level >= parameters_.nearSingularLevels || !isNear(x0, image, numImages, piece)) {
    out.push_back(piece);
    return;
  }
  const double middle = 0.5 * (piece.ta + piece.tb);
  bisect(k, x0, image, numImages, {piece.ta, middle, piece.poleAtStart, false, piece.level + 1, 2 * piece.index},
         level + 1, out);
  bisect(k, x0, image, numImages, {middle, piece.tb, false, piece.poleAtEnd, piece.level + 1, 2 * piece.index + 1},
         level + 1, out);
}

template <class Kernel>
void LayerPotentials2D<Kernel>::pieces(int k, const double* x0, bool poleAtStart, bool poleAtEnd,
                                       std::vector<SegmentPiece2D>& out) const
{
  out.clear();
  const SegmentPiece2D whole{0.0, 1.0, poleAtStart, poleAtEnd, 0, 0, k};
  if (!(parameters_.nearSingularDistance > 0.0)) {
    out.push_back(whole);
    return;
  }
  double image[KernelImages2D<Kernel>::count + 1][2];
  KernelImages2D<Kernel>::images(x0, image);
  bisect(k, x0, image, KernelImages2D<Kernel>::count, whole, 0, out);
}

template <class Kernel>
template <class Density>
const double* LayerPotentials2D<Kernel>::pieceGauss(int k, const SegmentPiece2D& piece, const Density& density) const
{
  const int perSegment = static_cast<int>(gauss_.points.size());
  CachedPiece& c = pieceCache_[static_cast<std::size_t>(piece.slot)];
  const std::vector<double>& s = contour_->parameters();
  const double span = (s[static_cast<std::size_t>(k) + 1] - s[static_cast<std::size_t>(k)]) * (c.tb - c.ta);
  const bool fresh = c.gauss < 0;
  if (fresh) {
    c.gauss = static_cast<int>(pieceGauss_.size() / gaussStride);
    pieceGauss_.resize(pieceGauss_.size() + static_cast<std::size_t>(gaussStride * perSegment));
  }
  double* g = &pieceGauss_[static_cast<std::size_t>(c.gauss) * gaussStride];
  if (fresh || c.densityCall != densityCall_) {
    for (int q = 0; q < perSegment; ++q) {
      const double t = c.ta + gauss_.points[q] * (c.tb - c.ta);
      const contour::ContourPoint point = contour_->pointAt(k, t);
      const double dl = gauss_.weights[q] * span * point.metric;
      const Eigen::Vector2d f = density(point, k, t) * dl;
      double* row = g + gaussStride * q;
      row[0] = point.position.x();
      row[1] = point.position.y();
      row[2] = dl;
      row[3] = f.x();
      row[4] = f.y();
    }
    c.densityCall = densityCall_;
  }
  return g;
}

namespace detail2d {

/// Calls visit(point, t, dl) at the Gauss points of piece [ta, tb] of segment k.
template <class Visit>
inline void visitGaussPiece(const contour::Contour& contour, const quadrature::Rule1D& rule, int k, double ta,
                            double tb, Visit&& visit)
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
  const int numPoints = quad.numberOfPoints();
  const std::vector<double>& s = c.parameters();
  ++densityCall_;

  // f dl at the regular points, once for all targets.
  {
    Teuchos::TimeMonitor guard(*loadTimer_);
    loadX_.resize(static_cast<std::size_t>(numPoints));
    loadY_.resize(static_cast<std::size_t>(numPoints));
    for (int p = 0; p < numPoints; ++p) {
      const Eigen::Vector2d f = density(quad.point(p), quad.segmentOf(p), quad.parameterOf(p));
      loadX_[p] = f.x() * quad.weights()[p];
      loadY_[p] = f.y() * quad.weights()[p];
    }
  }

  // Every regular pair at once (RegularSums2D.hpp).
  {
    Teuchos::TimeMonitor guard(*regularTimer_);
    sumX_.assign(static_cast<std::size_t>(paddedTargets_), 0.0);
    sumY_.assign(static_cast<std::size_t>(paddedTargets_), 0.0);
    RegularSums2DOf<Kernel>::addSums(pointX_.data(), pointY_.data(), loadX_.data(), loadY_.data(), perSegment, n,
                                     targetX_.data(), targetY_.data(), paddedTargets_, regularMask_.data(),
                                     sumX_.data(), sumY_.data());
  }

  // The pairs treated apart: the rules of singleLayerAtNodesReference on cached pieces.
  // Their Gauss points are gathered and evaluated in one vectorised pass; the ln tau
  // terms of the pole pieces go straight into specialU_.
  Teuchos::TimeMonitor guard(*specialTimer_);
  long long subdivided = 0;
  int count = 0; // pairs gathered; the buffers only grow (no allocation once warm)
  pairStart_.assign(static_cast<std::size_t>(numTargets_) + 1, 0);
  specialU_.assign(2 * static_cast<std::size_t>(numTargets_), 0.0);
  for (int t = 0; t < numTargets_; ++t) {
    const int m = firstTarget_ + t;
    const double x0[2] = {nodes_[2 * m], nodes_[2 * m + 1]};
    double u[2] = {0.0, 0.0};
    const auto gather = [&](double x, double y, double f0, double f1) {
      if (static_cast<std::size_t>(count) == pairX_.size()) {
        const std::size_t grown = std::max<std::size_t>(1024, 2 * pairX_.size());
        for (auto* buffer : {&pairX_, &pairY_, &pairFx_, &pairFy_, &pairX0_, &pairY0_, &pairUx_, &pairUy_}) {
          buffer->resize(grown);
        }
      }
      const auto i = static_cast<std::size_t>(count++);
      pairX_[i] = x;
      pairY_[i] = y;
      pairFx_[i] = f0;
      pairFy_[i] = f1;
      pairX0_[i] = x0[0];
      pairY0_[i] = x0[1];
    };
    for (int i = specialStart_[t]; i < specialStart_[t + 1]; ++i) {
      const int k = specialSegments_[static_cast<std::size_t>(i)];
      const bool poleAtStart = k == m;
      const bool poleAtEnd = (k + 1) % n == m;
      pieces(k, x0, poleAtStart, poleAtEnd, split_);
      subdivided += split_.size() > 1 ? 1 : 0;
      const double segmentSpan = s[static_cast<std::size_t>(k) + 1] - s[static_cast<std::size_t>(k)];
      for (const SegmentPiece2D& piece : split_) {
        // Gauss points of the piece: the regular points for a whole segment.
        const double* x;
        const double* y;
        const double* fx;
        const double* fy;
        int stride;
        if (piece.level == 0) {
          const int first = k * perSegment;
          x = &pointX_[first], y = &pointY_[first], fx = &loadX_[first], fy = &loadY_[first];
          stride = 1;
        } else {
          const double* g = pieceGauss(k, piece, density);
          x = g, y = g + 1, fx = g + 3, fy = g + 4;
          stride = gaussStride;
        }
        for (int q = 0; q < perSegment; ++q) {
          gather(x[q * stride], y[q * stride], fx[q * stride], fy[q * stride]);
        }
        if (!piece.poleAtStart && !piece.poleAtEnd) {
          continue;
        }
        // Gauss-Legendre in tau from the pole takes G + ln tau (tau = the point's own
        // parameter, or its mirror when the pole ends the piece), then the -ln tau rule.
        for (int q = 0; q < perSegment; ++q) {
          const double logTau = logGauss_[static_cast<std::size_t>(piece.poleAtStart ? q : mirror_[q])];
          u[0] += logTau * fx[q * stride];
          u[1] += logTau * fy[q * stride];
        }
        const double width = piece.tb - piece.ta;
        const double jacobian = segmentSpan * width; // ds / dtau
        for (std::size_t q = 0; q < logRule_.points.size(); ++q) {
          const double tau = logRule_.points[q];
          const double tp = piece.poleAtStart ? piece.ta + tau * width : piece.tb - tau * width;
          const contour::ContourPoint point = c.pointAt(k, tp);
          const Eigen::Vector2d f = density(point, k, tp) * (logRule_.weights[q] * jacobian * point.metric);
          u[0] += f.x();
          u[1] += f.y();
        }
      }
    }
    specialU_[2 * t] = u[0];
    specialU_[2 * t + 1] = u[1];
    pairStart_[t + 1] = count;
  }
  RegularSums2DOf<Kernel>::pairs(pairX_.data(), pairY_.data(), pairFx_.data(), pairFy_.data(), pairX0_.data(),
                                 pairY0_.data(), count, pairUx_.data(), pairUy_.data());
  for (int t = 0; t < numTargets_; ++t) {
    double u[2] = {specialU_[2 * t], specialU_[2 * t + 1]};
    for (int i = pairStart_[t]; i < pairStart_[t + 1]; ++i) {
      u[0] += pairUx_[static_cast<std::size_t>(i)];
      u[1] += pairUy_[static_cast<std::size_t>(i)];
    }
    result[2 * t] = sumX_[t] + u[0];
    result[2 * t + 1] = sumY_[t] + u[1];
  }
  subdivided_ = subdivided;
}

template <class Kernel>
template <class Density>
void LayerPotentials2D<Kernel>::singleLayerAtNodesReference(const Density& density, double* result) const
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
  const std::vector<double>& s = c.parameters();
  const auto span = [&s](int k) { return s[static_cast<std::size_t>(k) + 1] - s[static_cast<std::size_t>(k)]; };
  doubleLayer_.reset(n, c.closure() == contour::Closure::Periodic, paddedTargets_);

  // The regular pairs (mask 1) at the regular points, vectorised over the targets.
  std::vector<double> ax(static_cast<std::size_t>(numPoints)), ay(ax.size()), basis(4 * ax.size());
  for (int p = 0; p < numPoints; ++p) {
    ax[p] = quad.normals()[2 * p] * quad.weights()[p];
    ay[p] = quad.normals()[2 * p + 1] * quad.weights()[p];
    splineBasis(quad.parameterOf(p), span(quad.segmentOf(p)), &basis[4 * static_cast<std::size_t>(p)]);
  }
  RegularSums2DOf<Kernel>::addDoubleLayerCoefficients(pointX_.data(), pointY_.data(), ax.data(), ay.data(),
                                                      basis.data(), perSegment, n, targetX_.data(), targetY_.data(),
                                                      regularMask_.data(), doubleLayer_);

  // The pairs treated apart (mask 0): the segments ending at the target (the kernel is
  // bounded there, so they take the plain rule unless an image is near) and the bisected
  // ones, with the pieces of pieces().
  long long subdivided = 0;
  for (int t = 0; t < numTargets_; ++t) {
    const int m = firstTarget_ + t;
    const double x0[2] = {nodes_[2 * m], nodes_[2 * m + 1]};
    for (int i = specialStart_[t]; i < specialStart_[t + 1]; ++i) {
      const int k = specialSegments_[static_cast<std::size_t>(i)];
      pieces(k, x0, k == m, (k + 1) % n == m, split_);
      subdivided += split_.size() > 1 ? 1 : 0;
      for (const SegmentPiece2D& piece : split_) {
        detail2d::visitGaussPiece(
            c, gauss_, k, piece.ta, piece.tb, [&](const contour::ContourPoint& point, double tp, double dl) {
              double W[4];
              RegularSums2DOf<Kernel>::doubleLayerWeight(point.position.x(), point.position.y(), point.normal.x() * dl,
                                                         point.normal.y() * dl, x0[0], x0[1], W);
              doubleLayer_.addPoint(t, k, tp, span(k), W);
            });
      }
    }
  }
  subdivided_ = subdivided;
  hasDoubleWeights_ = true;
}

template <class Kernel>
void LayerPotentials2D<Kernel>::doubleLayerAtNodes(const double* nodalDensity, DoubleLayerForm form, double* result)
{
  if (!hasDoubleWeights_) {
    Teuchos::TimeMonitor guard(*doubleWeightsTimer_);
    buildDoubleLayerWeights();
  }
  Teuchos::TimeMonitor guard(*doubleApplyTimer_);
  doubleLayer_.apply(*contour_, nodalDensity, form == DoubleLayerForm::Subtracted, firstTarget_, numTargets_, result);
}

template <class Kernel>
template <class Density>
void LayerPotentials2D<Kernel>::singleLayerAtPoints(const double* points, int numberOfPoints, const Density& density,
                                                    double* result) const
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
