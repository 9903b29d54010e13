// The proxy charges of ClusterProxies: passed up the tree from the children's proxies,
// they equal the charges interpolated from the points directly (Wang, Tlupova & Krasny
// 2020, eq 14) to round-off, since a polynomial of the degree is its own interpolant.
#include <capsula/fastsum/BarycentricLagrange.hpp>
#include <capsula/fastsum/ClusterProxies.hpp>
#include <capsula/fastsum/Octree.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace capsula::fastsum;

TEST(ClusterProxies, UpwardChargesEqualThePointwiseInterpolation)
{
  std::mt19937 random(29);
  std::uniform_real_distribution<double> unit(0.0, 1.0), charge(-1.0, 1.0);
  const int n = 6000;
  std::vector<double> x(n), y(n), z(n), q(n);
  for (int k = 0; k < n; ++k) {
    x[k] = 3.0 * unit(random);
    y[k] = 0.5 * unit(random);
    z[k] = 2.0 * unit(random);
  }
  const Octree tree(x.data(), y.data(), z.data(), n, 40);
  for (const int degree : {2, 5}) {
    ClusterProxies proxies;
    proxies.build(tree, degree);
    std::vector<double> sorted(n);
    for (int k = 0; k < n; ++k) {
      sorted[k] = charge(random);
    }
    // Only the root used: every cluster below it with proxies is passed up.
    std::vector<char> used(tree.clusters().size(), 0);
    used[0] = 1;
    std::vector<std::vector<double>> charges;
    proxies.interpolateCharges(tree, {sorted.data()}, used, charges);
    ASSERT_TRUE(proxies.hasProxies(0));
    // eq 14 at the root: qhat_p = sum_q L_p1(x_q) L_p2(y_q) L_p3(z_q) q_q on its grid.
    const int m = degree + 1;
    const Cluster& root = tree.clusters()[0];
    double s[3][maxInterpolationDegree + 1];
    for (int axis = 0; axis < 3; ++axis) {
      chebyshevPoints(degree, root.box.lo[axis], root.box.hi[axis], s[axis]);
    }
    std::vector<double> expected(proxies.pointsPerCluster(), 0.0);
    for (int k = 0; k < n; ++k) {
      double L[3][maxInterpolationDegree + 1];
      lagrangeBasis(degree, s[0], tree.x()[k], L[0]);
      lagrangeBasis(degree, s[1], tree.y()[k], L[1]);
      lagrangeBasis(degree, s[2], tree.z()[k], L[2]);
      for (int i = 0; i < m; ++i) {
        for (int j = 0; j < m; ++j) {
          for (int l = 0; l < m; ++l) {
            expected[(i * m + j) * m + l] += L[0][i] * L[1][j] * L[2][l] * sorted[k];
          }
        }
      }
    }
    double worst = 0.0, scale = 0.0;
    for (int p = 0; p < proxies.pointsPerCluster(); ++p) {
      worst = std::max(worst, std::abs(charges[0][proxies.offset(0) + p] - expected[p]));
      scale = std::max(scale, std::abs(expected[p]));
    }
    EXPECT_LT(worst, 1e-11 * scale) << "degree " << degree;
  }
}
