#include "capsula/timeint/RosenbrockTableau.hpp"

#include "capsula/core/Error.hpp"

#include <algorithm>
#include <cmath>

namespace capsula::timeint {

namespace {

// x = L^-1 rhs for lower-triangular L (row-major, n x n).
std::vector<double> forwardSubstitution(const std::vector<double>& L, const std::vector<double>& rhs, int n)
{
  std::vector<double> x(rhs);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < i; ++j) {
      x[static_cast<std::size_t>(i)] -= L[static_cast<std::size_t>(i * n + j)] * x[static_cast<std::size_t>(j)];
    }
    x[static_cast<std::size_t>(i)] /= L[static_cast<std::size_t>(i * n + i)];
  }
  return x;
}

// Solves x^T L = w^T, i.e. L^T x = w, for lower-triangular L.
std::vector<double> transposedBackSubstitution(const std::vector<double>& L, const std::vector<double>& w, int n)
{
  std::vector<double> x(w);
  for (int i = n - 1; i >= 0; --i) {
    for (int j = i + 1; j < n; ++j) {
      x[static_cast<std::size_t>(i)] -= L[static_cast<std::size_t>(j * n + i)] * x[static_cast<std::size_t>(j)];
    }
    x[static_cast<std::size_t>(i)] /= L[static_cast<std::size_t>(i * n + i)];
  }
  return x;
}

} // namespace

int RosenbrockTableau::errorEstimateOrder() const
{
  return std::min(order, embeddedOrder) + 1;
}

void transformRosenbrockTableau(RosenbrockTableau& t)
{
  const int s = t.stages;
  const auto ss = static_cast<std::size_t>(s * s);
  core::require(s >= 1 && t.alpha.size() == ss && t.gammaOffDiagonal.size() == ss &&
                    t.b.size() == static_cast<std::size_t>(s) && t.bEmbedded.size() == static_cast<std::size_t>(s) &&
                    t.gamma > 0.0,
                "internal: inconsistent Rosenbrock tableau ", t.name);
  std::vector<double> Gamma = t.gammaOffDiagonal;
  for (int i = 0; i < s; ++i) {
    Gamma[static_cast<std::size_t>(i * s + i)] = t.gamma;
  }
  // Gamma^-1 column by column.
  std::vector<double> inverse(ss, 0.0);
  for (int j = 0; j < s; ++j) {
    std::vector<double> e(static_cast<std::size_t>(s), 0.0);
    e[static_cast<std::size_t>(j)] = 1.0;
    const std::vector<double> column = forwardSubstitution(Gamma, e, s);
    for (int i = 0; i < s; ++i) {
      inverse[static_cast<std::size_t>(i * s + j)] = column[static_cast<std::size_t>(i)];
    }
  }
  t.a.assign(ss, 0.0);
  t.c.assign(ss, 0.0);
  t.stageTime.assign(static_cast<std::size_t>(s), 0.0);
  for (int i = 0; i < s; ++i) {
    for (int j = 0; j < i; ++j) {
      double sum = 0.0;
      for (int k = j; k < i; ++k) { // alpha is strictly lower, Gamma^-1 lower
        sum += t.alpha[static_cast<std::size_t>(i * s + k)] * inverse[static_cast<std::size_t>(k * s + j)];
      }
      t.a[static_cast<std::size_t>(i * s + j)] = sum;
      t.c[static_cast<std::size_t>(i * s + j)] = -inverse[static_cast<std::size_t>(i * s + j)];
      t.stageTime[static_cast<std::size_t>(i)] += t.alpha[static_cast<std::size_t>(i * s + j)];
    }
  }
  t.m = transposedBackSubstitution(Gamma, t.b, s);
  t.mEmbedded = transposedBackSubstitution(Gamma, t.bEmbedded, s);
}

double rosenbrockStabilityFunction(const RosenbrockTableau& t, double z)
{
  // x = (I - z (alpha + Gamma))^-1 1 by forward substitution (the matrix is lower triangular).
  const int s = t.stages;
  std::vector<double> L(static_cast<std::size_t>(s * s), 0.0);
  for (int i = 0; i < s; ++i) {
    for (int j = 0; j < i; ++j) {
      const auto ij = static_cast<std::size_t>(i * s + j);
      L[ij] = -z * (t.alpha[ij] + t.gammaOffDiagonal[ij]);
    }
    L[static_cast<std::size_t>(i * s + i)] = 1.0 - z * t.gamma;
  }
  const std::vector<double> x = forwardSubstitution(L, std::vector<double>(static_cast<std::size_t>(s), 1.0), s);
  double sum = 0.0;
  for (int i = 0; i < s; ++i) {
    sum += t.b[static_cast<std::size_t>(i)] * x[static_cast<std::size_t>(i)];
  }
  return 1.0 + z * sum;
}

RosenbrockTableau ros34pw2()
{
  RosenbrockTableau t;
  t.name = "ROS34PW2";
  t.stages = 4;
  t.order = 3;
  t.embeddedOrder = 2;
  t.gamma = 4.3586652150845900e-1;
  t.alpha = {
      0.0, 0.0, 0.0, 0.0, 8.7173304301691801e-1, 0.0, 0.0, 0.0, 8.4457060015369423e-1, -1.1299064236484185e-1, 0.0, 0.0,
      0.0, 0.0, 1.0, 0.0};
  t.gammaOffDiagonal = {0.0,
                        0.0,
                        0.0,
                        0.0,
                        -8.7173304301691801e-1,
                        0.0,
                        0.0,
                        0.0,
                        -9.0338057013044082e-1,
                        5.4180672388095326e-2,
                        0.0,
                        0.0,
                        2.4212380706095346e-1,
                        -1.2232505839045147,
                        5.4526025533510214e-1,
                        0.0};
  t.b = {2.4212380706095346e-1, -1.2232505839045147, 1.5452602553351020, 4.3586652150845900e-1};
  t.bEmbedded = {3.7810903145819369e-1, -9.6042292212423178e-2, 0.5, 2.1793326075422950e-1};
  transformRosenbrockTableau(t);
  return t;
}

RosenbrockTableau ros2()
{
  // Verwer et al. write the method in the transformed variables u_i / gamma:
  // (I - g h J) k1 = h f(y), (I - g h J) k2 = h f(y + k1) - 2 k1, y_new = y + 3/2 k1 + 1/2 k2,
  // the embedded solution y + k1. In the standard form that is alpha_21 = 1,
  // gamma_21 = -2 g, b = (1/2, 1/2), bEmbedded = (1, 0) (a = alpha Gamma^-1 etc. give back
  // a_21 = 1/g, c_21 = -2/g, m = (3/2, 1/2)/g).
  RosenbrockTableau t;
  t.name = "ROS2";
  t.stages = 2;
  t.order = 2;
  t.embeddedOrder = 1;
  t.gamma = 1.0 + 1.0 / std::sqrt(2.0);
  t.alpha = {0.0, 0.0, 1.0, 0.0};
  t.gammaOffDiagonal = {0.0, 0.0, -2.0 * t.gamma, 0.0};
  t.b = {0.5, 0.5};
  t.bEmbedded = {1.0, 0.0};
  transformRosenbrockTableau(t);
  return t;
}

} // namespace capsula::timeint
