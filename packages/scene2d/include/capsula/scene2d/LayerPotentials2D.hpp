#pragma once
// (One class template per Green's function, instantiated in InterfaceVelocity2D.cpp; its
// geometry cache, pair classification and the layer sums share the members that the hot
// loops inline across. Their definitions are in the two headers included at the end:
// LayerPotentials2DGeometry.hpp and LayerPotentials2DEvaluation.hpp.)
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
// by the same vectorised pair formula. tests/unit/scene2d/test_single_layer_fast_2d.cpp
// evaluates the same rules pair by pair on the same pieces() as the reference of this path.
// The caches make the const evaluations unsafe to call concurrently on one object.
#include "capsula/scene2d/ContourDiscretisation2D.hpp"
#include "capsula/scene2d/ContourQuadrature2D.hpp"
#include "capsula/scene2d/RegularSums2D.hpp"
#include "capsula/scene2d/SplineDoubleLayer2D.hpp"

#include <capsula/contour/Contour.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/core/Timers.hpp>
#include <capsula/greens/FreeSpace2D.hpp>
#include <capsula/greens/Wall2D.hpp>
#include <capsula/operators/DoubleLayerForm.hpp>
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

namespace capsula::scene2d {

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
/// Each kernel names its four functions; the calls through these constant pointers are direct.
template <class Kernel>
struct RegularSums2DOf;

template <>
struct RegularSums2DOf<greens::Wall2D> {
  static constexpr auto addSums = addWallStokesletSums2D;
  static constexpr auto pairs = wallStokesletPairs2D;
  static constexpr auto doubleLayerWeight = wallDoubleLayerWeight2D;
  static constexpr auto addDoubleLayerCoefficients = addWallDoubleLayerCoefficients2D;
};

template <>
struct RegularSums2DOf<greens::FreeSpace2D> {
  static constexpr auto addSums = addFreeSpaceStokesletSums2D;
  static constexpr auto pairs = freeSpaceStokesletPairs2D;
  static constexpr auto doubleLayerWeight = freeSpaceDoubleLayerWeight2D;
  static constexpr auto addDoubleLayerCoefficients = addFreeSpaceDoubleLayerCoefficients2D;
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

  /// result[2 t + j] = PV int u_i T_ijk(x, x_t) n_k dl at the target nodes, for u given at
  /// every node (2 per node). The map from the density's spline data to these values
  /// (SplineDoubleLayer2D) is built on the first call after update() and reused (the GMRES
  /// iterations apply this repeatedly on one geometry).
  void doubleLayerAtNodes(const double* nodalDensity, operators::DoubleLayerForm form, double* result);

  /// The same at n points off the contour (2 per point) and for a density at any point.
  template <class Density>
  void singleLayerAtPoints(const double* points, int n, const Density& density, double* result) const;
  void doubleLayerAtPoints(const double* points, int n, const double* nodalDensity, double* result) const;

  /// Segment pieces that were bisected at the node targets in the last single- or
  /// double-layer build (diagnostics).
  long long subdividedSegments() const { return subdivided_; }

  /// The pieces segment k is split into for the pole x0 (its near-singular bisection, the
  /// whole segment when far), and whether x0 is the segment's start or end node; pieces
  /// touching the pole are judged by the images only. Valid after update().
  void pieces(int k, const double* x0, bool poleAtStart, bool poleAtEnd, std::vector<SegmentPiece2D>& out) const;

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

} // namespace capsula::scene2d

#include "capsula/scene2d/LayerPotentials2DGeometry.hpp"
#include "capsula/scene2d/LayerPotentials2DEvaluation.hpp"
