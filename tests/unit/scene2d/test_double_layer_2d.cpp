// The 2D double layer at the nodes as coefficients on the density's spline data
// (SplineDoubleLayer2D, built by LayerPotentials2D) against the plain sum over the
// quadrature points of W(x_q, x_t) u(x_q), u evaluated by the density's own spline
// (ContourField2D), and the double-layer pair formulas of RegularSums2D.hpp against the
// stresslets of packages/greens.
#include "Contour2DTesting.hpp"

#include <capsula/greens/FreeSpace2D.hpp>
#include <capsula/greens/Wall2D.hpp>
#include <capsula/scene2d/ContourQuadrature2D.hpp>
#include <capsula/scene2d/LayerPotentials2D.hpp>
#include <capsula/scene2d/RegularSums2D.hpp>
#include <capsula/scene2d/SplineDoubleLayer2D.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace {

using namespace capsula;
using capsula::scene2d::ContourDiscretisation2D;
using capsula::scene2d::LayerPotentials2D;

TEST(RegularSums2D, DoubleLayerWeightsAreTheStressletsAppliedToTheNormal)
{
  // W_ij = T_ijk a_k written out against greens::stressletWall2D / stressletFreeSpace2D,
  // for poles down to 1e-4 above the wall and field points from 1e-5 to 3 away. The image
  // system cancels the free-space stresslet to the result near the wall, so the bound is
  // relative to the size of the terms, the largest entry of the free-space stresslets of
  // the pole and of its image times |a|: 1e-14 (measured 8e-16; a wrong sign or factor in
  // any term is O(1)).
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), logDistance(-5.0, 0.5), logHeight(-4.0, 0.3);
  double worstWall = 0.0, worstFree = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const double x0[2] = {unit(random), std::pow(10.0, logHeight(random))};
    const double angle = M_PI * unit(random), r = std::pow(10.0, logDistance(random));
    const double x[2] = {x0[0] + r * std::cos(angle), x0[1] + r * std::sin(angle)};
    if (!(x[1] > 0.0)) {
      continue;
    }
    const double a[2] = {unit(random), unit(random)};
    const double xh[2] = {x[0] - x0[0], x[1] - x0[1]};
    const double X[2] = {x[0] - x0[0], x[1] + x0[1]};
    double Tpole[2][2][2], Timage[2][2][2];
    greens::stressletFreeSpace2D(xh, Tpole);
    greens::stressletFreeSpace2D(X, Timage);
    double termSize = 0.0;
    for (int i2 = 0; i2 < 2; ++i2) {
      for (int j = 0; j < 2; ++j) {
        for (int k = 0; k < 2; ++k) {
          termSize = std::max({termSize, std::abs(Tpole[i2][j][k]), std::abs(Timage[i2][j][k])});
        }
      }
    }
    const auto worst = [&](const double(&T)[2][2][2], const double W[4]) {
      double scale = termSize, error = 0.0;
      for (int i2 = 0; i2 < 2; ++i2) {
        for (int j = 0; j < 2; ++j) {
          scale = std::max({scale, std::abs(T[i2][j][0]), std::abs(T[i2][j][1])});
        }
      }
      scale *= std::abs(a[0]) + std::abs(a[1]);
      for (int i2 = 0; i2 < 2; ++i2) {
        for (int j = 0; j < 2; ++j) {
          error = std::max(error, std::abs(W[2 * i2 + j] - (T[i2][j][0] * a[0] + T[i2][j][1] * a[1])));
        }
      }
      return error / scale;
    };
    double T[2][2][2], W[4];
    greens::stressletWall2D(x, x0, T);
    scene2d::wallDoubleLayerWeight2D(x[0], x[1], a[0], a[1], x0[0], x0[1], W);
    worstWall = std::max(worstWall, worst(T, W));
    greens::stressletFreeSpace2D(xh, T);
    scene2d::freeSpaceDoubleLayerWeight2D(x[0], x[1], a[0], a[1], x0[0], x0[1], W);
    worstFree = std::max(worstFree, worst(T, W));
  }
  std::printf("  worst relative errors: wall %.2g, free space %.2g\n", worstWall, worstFree);
  EXPECT_LT(worstWall, 1e-14);
  EXPECT_LT(worstFree, 1e-14);
}

TEST(SplineDoubleLayer2D, BasisReproducesTheSplinePieces)
{
  // u(tau) = (1 - tau) u_k + tau u_k+1 + h^2/6 [((1-tau)^3 - (1-tau)) M_k + (tau^3 - tau) M_k+1]
  // is the spline of eq A.15 on its piece: compared with CubicSpline's own pieces at
  // random parameters of a natural and a periodic spline through uneven knots.
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> knots{0.0}, values;
  for (int k = 0; k < 12; ++k) {
    knots.push_back(knots.back() + 0.2 + unit(random));
    values.push_back(std::sin(3.0 * knots[k]) + unit(random));
  }
  const std::vector<double> open = [&] {
    auto v = values;
    v.push_back(0.4);
    return v;
  }();
  for (const auto& spline :
       {contour::CubicSpline::natural(knots, open), contour::CubicSpline::periodic(knots, values)}) {
    const int pieces = spline.numberOfPieces();
    std::vector<double> u(static_cast<std::size_t>(pieces) + 1), M(u.size());
    for (int k = 0; k <= pieces; ++k) {
      const int piece = std::min(k, pieces - 1);
      const double h = knots[piece + 1] - knots[piece];
      const contour::CubicPiece& p = spline.piece(piece);
      u[k] = k == piece ? p.d : p.value(h);
      M[k] = k == piece ? 2.0 * p.b : 6.0 * p.a * h + 2.0 * p.b;
    }
    for (int k = 0; k < pieces; ++k) {
      const double h = knots[k + 1] - knots[k];
      for (int i = 0; i < 5; ++i) {
        const double tau = unit(random);
        double b[4];
        scene2d::splineBasis(tau, h, b);
        const double fromBasis = b[0] * u[k] + b[1] * u[k + 1] + b[2] * M[k] + b[3] * M[k + 1];
        // Round-off of values of size ~2 (the pieces' own cubic in ds = tau h).
        EXPECT_NEAR(fromBasis, spline.piece(k).value(tau * h), 1e-13) << "piece " << k;
      }
    }
  }
}

/// The double layer at the nodes of `c` summed point by point over the regular quadrature
/// (every pair regular: subdivision off), u splined by ContourField2D as the operator does.
template <class Kernel>
std::vector<double> pointByPointDoubleLayer(const contour::Contour& c, const ContourDiscretisation2D& d,
                                            const std::vector<double>& density, bool subtract)
{
  const scene2d::ContourQuadrature2D quad(c, quadrature::gaussLegendre(d.gaussLegendrePoints));
  const scene2d::ContourField2D field(c, density.data());
  std::vector<double> result(2 * static_cast<std::size_t>(c.numberOfNodes()), 0.0);
  for (int m = 0; m < c.numberOfNodes(); ++m) {
    const double x0[2] = {c.nodes()(0, m), c.nodes()(1, m)};
    double sum[2] = {0.0, 0.0};
    for (int p = 0; p < quad.numberOfPoints(); ++p) {
      const double a[2] = {quad.normals()[2 * p] * quad.weights()[p], quad.normals()[2 * p + 1] * quad.weights()[p]};
      double W[4];
      scene2d::doubleLayerWeight2D<Kernel>(&quad.positions()[2 * p], x0, a, W);
      Eigen::Vector2d u = field.at(quad.segmentOf(p), quad.parameterOf(p));
      if (subtract) {
        u -= Eigen::Vector2d(density[2 * m], density[2 * m + 1]);
      }
      sum[0] += u.x() * W[0] + u.y() * W[2];
      sum[1] += u.x() * W[1] + u.y() * W[3];
    }
    result[2 * m] = sum[0] - (subtract ? 2.0 * M_PI * density[2 * m] : 0.0);
    result[2 * m + 1] = sum[1] - (subtract ? 2.0 * M_PI * density[2 * m + 1] : 0.0);
  }
  return result;
}

TEST(SplineDoubleLayer2D, EqualsThePointByPointSumForFreeAndTetheredContours)
{
  // A density with both components and no symmetry (so that the second-derivative terms
  // of the spline matter), on a free (periodic) and a tethered (natural, through the tether
  // node) ellipse, free space and above the wall, both forms. Subdivision off: every pair
  // then takes the plain Gauss-Legendre rule in both evaluations, the segments ending at
  // the target (the special pairs of the coefficient build) included. The two sum the
  // same terms in another order: round-off of sums of size ~10 (measured ~1e-14).
  ContourDiscretisation2D d;
  d.nearSingularDistance = 0.0;
  for (const auto closure : {contour::Closure::Periodic, contour::Closure::Tethered}) {
    const auto c = scene2d::testing2d::ellipse(40, 0.5, {0.1, 2.0}, closure);
    std::vector<double> density(2 * static_cast<std::size_t>(c.numberOfNodes()));
    for (int m = 0; m < c.numberOfNodes(); ++m) {
      const double x = c.nodes()(0, m), y = c.nodes()(1, m);
      density[2 * m] = std::sin(2.0 * x) + 0.3 * y;
      density[2 * m + 1] = std::cos(3.0 * y) - 0.5 * x * y;
    }
    for (const bool subtract : {true, false}) {
      const auto form = subtract ? operators::DoubleLayerForm::Subtracted : operators::DoubleLayerForm::Direct;
      const auto check = [&](auto layers, const std::vector<double>& expected, const char* kernel) {
        layers.update(c, 0, c.numberOfNodes());
        std::vector<double> result(expected.size());
        layers.doubleLayerAtNodes(density.data(), form, result.data());
        for (std::size_t i = 0; i < result.size(); ++i) {
          EXPECT_NEAR(result[i], expected[i], 1e-12) << kernel << ", entry " << i << ", subtract " << subtract;
        }
      };
      check(LayerPotentials2D<greens::FreeSpace2D>(d),
            pointByPointDoubleLayer<greens::FreeSpace2D>(c, d, density, subtract), "free space");
      check(LayerPotentials2D<greens::Wall2D>(d), pointByPointDoubleLayer<greens::Wall2D>(c, d, density, subtract),
            "wall");
    }
  }
}

TEST(SplineDoubleLayer2D, OnlyTheOwnedTargetsAreEvaluated)
{
  // Rows of a rank's share (targets 7 .. 7 + 13) equal the same rows of the whole contour:
  // the coefficients are per target lane, and the subtraction takes each target's own node.
  ContourDiscretisation2D d;
  const auto c = scene2d::testing2d::ellipse(32, 0.5, {0.0, 1.5});
  std::vector<double> density(2 * static_cast<std::size_t>(c.numberOfNodes()));
  for (std::size_t i = 0; i < density.size(); ++i) {
    density[i] = std::cos(0.7 * static_cast<double>(i));
  }
  LayerPotentials2D<greens::Wall2D> whole(d), share(d);
  whole.update(c, 0, c.numberOfNodes());
  share.update(c, 7, 13);
  std::vector<double> all(density.size()), part(26);
  whole.doubleLayerAtNodes(density.data(), operators::DoubleLayerForm::Subtracted, all.data());
  share.doubleLayerAtNodes(density.data(), operators::DoubleLayerForm::Subtracted, part.data());
  for (int t = 0; t < 13; ++t) {
    EXPECT_EQ(part[2 * t], all[2 * (7 + t)]) << "target " << t;
    EXPECT_EQ(part[2 * t + 1], all[2 * (7 + t) + 1]) << "target " << t;
  }
}

} // namespace
