// The fast path of the 2D single layer (LayerPotentials2D::singleLayerAtNodes: vectorised
// regular sums, pair classification by squared distances, cached bisected pieces) against
// the plain pair-by-pair evaluation of the same rules on the same pieces, and
// the pieces it is built from: the vectorisable logarithm and the pair formulas of
// RegularSums2D.hpp against std::log and the Green's functions of packages/greens.
#include "Contour2DTesting.hpp"

#include <capsula/greens/FreeSpace2D.hpp>
#include <capsula/greens/Wall2D.hpp>
#include <capsula/scene2d/LayerPotentials2D.hpp>
#include <capsula/scene2d/RegularSums2D.hpp>
#include <capsula/operators/VectorisableLog.hpp>
#include <capsula/quadrature/GaussLegendre.hpp>
#include <capsula/quadrature/LogWeightedGauss.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using namespace capsula;
using capsula::scene2d::ContourDiscretisation2D;
using capsula::scene2d::LayerPotentials2D;
using capsula::scene2d::SegmentPiece2D;

constexpr double eps = std::numeric_limits<double>::epsilon();

TEST(VectorisableLog, AgreesWithStdLogToAFewUnitsInTheLastPlace)
{
  // Squared distances and their ratios in the 2D sums run from ~1e-10 to ~1e2; the range
  // tested is far wider, and densely sampled around 1 where ln x -> 0. The bound, 4 ulp of
  // |ln x| (or of 1e-300 at x = 1), is what the e ln 2 + 2 atanh f reduction guarantees:
  // one rounding in f, one in the series, two in the sums (measured: 1.9 ulp).
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> exponent(-30.0, 30.0), nearOne(-1e-3, 1e-3);
  std::vector<double> xs{1.0, 2.0, 0.5, std::sqrt(2.0), std::sqrt(0.5), 1e-300, 1e300, 1.0 + eps, 1.0 - eps / 2};
  for (int i = 0; i < 20000; ++i) {
    xs.push_back(std::pow(10.0, exponent(random)));
    xs.push_back(1.0 + nearOne(random));
  }
  for (const double x : xs) {
    const double exact = std::log(x);
    const double scale = std::max(std::abs(exact), 1e-300);
    ASSERT_LE(std::abs(operators::vectorisableLog(x) - exact), 4.0 * eps * scale) << "x = " << x;
  }
}

TEST(RegularSums2D, PairFormulasAreTheGreensFunctionsAppliedToTheForce)
{
  // u_j = G_ij f_i written out (one logarithm, one division for the wall) against
  // greens::stokesletWall2D / stokesletFreeSpace2D, for poles down to 1e-4 above the wall
  // and field points from 1e-5 to 3 away. Terms of size up to ~|ln r| + 1 cancel to the
  // result, so the bound is relative to the largest term: 1e-14 (measured 2e-16).
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), logDistance(-5.0, 0.5), logHeight(-4.0, 0.3);
  double worstWall = 0.0, worstFree = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const double x0[2] = {unit(random), std::pow(10.0, logHeight(random))};
    const double angle = M_PI * unit(random), r = std::pow(10.0, logDistance(random));
    const double x[2] = {x0[0] + r * std::cos(angle), x0[1] + r * std::sin(angle)};
    if (!(x[1] > 0.0)) {
      continue; // field points in the fluid too
    }
    const double f[2] = {unit(random), unit(random)};
    double G[2][2];
    greens::stokesletWall2D(x, x0, G);
    const double scale = (std::abs(std::log(r)) + 10.0) * (std::abs(f[0]) + std::abs(f[1]));
    double u[2] = {0.0, 0.0};
    scene2d::addWallStokesletPair2D(x[0], x[1], f[0], f[1], x0[0], x0[1], u[0], u[1]);
    for (int j = 0; j < 2; ++j) {
      worstWall = std::max(worstWall, std::abs(u[j] - (G[0][j] * f[0] + G[1][j] * f[1])) / scale);
    }
    const double xh[2] = {x[0] - x0[0], x[1] - x0[1]};
    greens::stokesletFreeSpace2D(xh, G);
    double v[2] = {0.0, 0.0};
    scene2d::addFreeSpaceStokesletPair2D(x[0], x[1], f[0], f[1], x0[0], x0[1], v[0], v[1]);
    for (int j = 0; j < 2; ++j) {
      worstFree = std::max(worstFree, std::abs(v[j] - (G[0][j] * f[0] + G[1][j] * f[1])) / scale);
    }
  }
  EXPECT_LT(worstWall, 1e-14);
  EXPECT_LT(worstFree, 1e-14);
}

/// A smooth load with both components and no symmetry: the normal times a varying
/// tension plus a tangential part.
Eigen::Vector2d someLoad(const contour::ContourPoint& p, int, double)
{
  return (1.0 + 0.3 * std::cos(3.0 * p.position.x())) * p.normal + 0.2 * std::sin(2.0 * p.position.y()) * p.tangent;
}

/// The reference of the fast path: the rules singleLayerAtNodes applies (LayerPotentials2D.hpp),
/// evaluated pair by pair on the pieces LayerPotentials2D::pieces gives, without the
/// vectorised sums, the pair classification or the piece cache: the regular rule on a piece
/// away from the pole; on a piece that ends at it, Gauss-Legendre in tau from the pole on
/// G + ln tau, then the -ln tau rule. Returns the segments bisected for the targets.
template <class Kernel, class Density>
long long singleLayerPairByPair(const LayerPotentials2D<Kernel>& layers, const Density& density, double* result)
{
  const contour::Contour& c = layers.contour();
  const int n = c.numberOfNodes();
  const quadrature::Rule1D gauss = quadrature::gaussLegendre(layers.parameters().gaussLegendrePoints);
  const quadrature::Rule1D logRule = quadrature::logWeightedGauss(layers.parameters().logWeightedPoints);
  const std::vector<double>& s = c.parameters();
  std::vector<SegmentPiece2D> split;
  long long subdivided = 0;
  for (int t = 0; t < layers.numTargets(); ++t) {
    const int m = layers.firstTarget() + t;
    const double x0[2] = {c.nodes()(0, m), c.nodes()(1, m)};
    double u[2] = {0.0, 0.0};
    for (int k = 0; k < n; ++k) {
      layers.pieces(k, x0, k == m, (k + 1) % n == m, split);
      subdivided += split.size() > 1 ? 1 : 0;
      const double segmentSpan = s[static_cast<std::size_t>(k) + 1] - s[static_cast<std::size_t>(k)];
      for (const SegmentPiece2D& piece : split) {
        if (!piece.poleAtStart && !piece.poleAtEnd) {
          scene2d::detail2d::visitGaussPiece(c, gauss, k, piece.ta, piece.tb,
                                             [&](const contour::ContourPoint& point, double tp, double dl) {
                                               const Eigen::Vector2d f = density(point, k, tp) * dl;
                                               const double fx[2] = {f.x(), f.y()};
                                               const double x[2] = {point.position.x(), point.position.y()};
                                               scene2d::addSingleLayerTerm2D<Kernel>(x, x0, fx, u);
                                             });
          continue;
        }
        // tau from the pole: t = ta + tau (tb - ta) or t = tb - tau (tb - ta).
        const double width = piece.tb - piece.ta;
        const auto parameterAt = [&](double tau) {
          return piece.poleAtStart ? piece.ta + tau * width : piece.tb - tau * width;
        };
        const double jacobian = segmentSpan * width; // ds / dtau
        for (std::size_t q = 0; q < gauss.points.size(); ++q) {
          const double tau = gauss.points[q];
          const double tp = parameterAt(tau);
          const contour::ContourPoint point = c.pointAt(k, tp);
          const Eigen::Vector2d f = density(point, k, tp) * (gauss.weights[q] * jacobian * point.metric);
          const double x[2] = {point.position.x(), point.position.y()};
          double G[2][2];
          Kernel::stokeslet(x, x0, G);
          const double logTau = std::log(tau);
          G[0][0] += logTau;
          G[1][1] += logTau;
          u[0] += G[0][0] * f.x() + G[1][0] * f.y();
          u[1] += G[0][1] * f.x() + G[1][1] * f.y();
        }
        for (std::size_t q = 0; q < logRule.points.size(); ++q) {
          const double tp = parameterAt(logRule.points[q]);
          const contour::ContourPoint point = c.pointAt(k, tp);
          const Eigen::Vector2d f = density(point, k, tp) * (logRule.weights[q] * jacobian * point.metric);
          u[0] += f.x();
          u[1] += f.y();
        }
      }
    }
    result[2 * t] = u[0];
    result[2 * t + 1] = u[1];
  }
  return subdivided;
}

template <class Kernel, class Density>
double fastMinusReference(const contour::Contour& c, const ContourDiscretisation2D& d, int first, int count,
                          const Density& density, long long* subdividedFast = nullptr,
                          long long* subdividedReference = nullptr)
{
  LayerPotentials2D<Kernel> layers(d);
  layers.update(c, first, count);
  std::vector<double> fast(2 * count), reference(2 * count);
  layers.singleLayerAtNodes(density, fast.data());
  if (subdividedFast != nullptr) {
    *subdividedFast = layers.subdividedSegments();
  }
  const long long referencePieces = singleLayerPairByPair(layers, density, reference.data());
  if (subdividedReference != nullptr) {
    *subdividedReference = referencePieces;
  }
  double difference = 0.0, size = 0.0;
  for (int i = 0; i < 2 * count; ++i) {
    difference = std::max(difference, std::abs(fast[i] - reference[i]));
    size = std::max(size, std::abs(reference[i]));
  }
  return difference / size;
}

TEST(LayerPotentials2D, FastSingleLayerEqualsTheReferenceNearTheWall)
{
  // An elongated cell 0.005 above the wall (the thesis's gap: every target near the bottom
  // bisects segments against its image) and one far from it, on all nodes and on an
  // uneven block of them (as a rank owns: padding lanes in the vectorised sums). The two
  // paths apply the same rules with the same pieces and differ only in summation order,
  // the one-logarithm wall kernel and the cache: 1e-13 of the largest value is ~1000
  // roundings of the ~1500-term sums (measured: 3.8e-15 .. 5.9e-15).
  ContourDiscretisation2D d; // thesis settings plus the default subdivision
  for (const double gap : {0.005, 0.5}) {
    const contour::Contour c = scene2d::testing2d::ellipse(128, 2.0, {0.3, 1.0 / std::sqrt(2.0) + gap});
    long long fastPieces = 0, referencePieces = 0;
    EXPECT_LT(fastMinusReference<greens::Wall2D>(c, d, 0, 128, someLoad, &fastPieces, &referencePieces), 1e-13)
        << "gap " << gap;
    EXPECT_EQ(fastPieces, referencePieces) << "gap " << gap;
    if (gap < 0.01) {
      EXPECT_GT(fastPieces, 128) << "the test must exercise the near-singular rules";
    }
    EXPECT_LT(fastMinusReference<greens::Wall2D>(c, d, 37, 53, someLoad), 1e-13) << "gap " << gap;
    EXPECT_LT(fastMinusReference<greens::FreeSpace2D>(c, d, 5, 101, someLoad), 1e-13) << "gap " << gap;
  }
}

TEST(LayerPotentials2D, FastSingleLayerEqualsTheReferenceForEverySubdivisionSetting)
{
  // No subdivision (thesis practice), bisection without levels, and deep bisection; and a
  // second density on the same geometry (the piece cache must not reuse the first one's
  // loads). Bound as above (measured: 1.2e-15 .. 3.5e-15).
  const contour::Contour c = scene2d::testing2d::ellipse(64, 1.0, {0.0, 1.002});
  for (const auto& [distance, bisections] : {std::pair{0.0, 8}, std::pair{2.0, 0}, std::pair{3.0, 12}}) {
    ContourDiscretisation2D d;
    d.nearSingularDistance = distance;
    d.nearSingularLevels = bisections;
    EXPECT_LT(fastMinusReference<greens::Wall2D>(c, d, 0, 64, someLoad), 1e-13)
        << "distance " << distance << ", bisections " << bisections;
  }
  ContourDiscretisation2D d;
  LayerPotentials2D<greens::Wall2D> layers(d);
  layers.update(c, 0, 64);
  const auto other = [](const contour::ContourPoint& p, int, double) -> Eigen::Vector2d {
    return Eigen::Vector2d(p.position.y(), 1.0 - p.position.x());
  };
  std::vector<double> first(128), fast(128), reference(128);
  layers.singleLayerAtNodes(someLoad, first.data());
  layers.singleLayerAtNodes(other, fast.data());
  singleLayerPairByPair(layers, other, reference.data());
  double difference = 0.0, size = 0.0;
  for (int i = 0; i < 128; ++i) {
    difference = std::max(difference, std::abs(fast[i] - reference[i]));
    size = std::max(size, std::abs(reference[i]));
  }
  EXPECT_LT(difference, 1e-13 * size);
}

} // namespace
