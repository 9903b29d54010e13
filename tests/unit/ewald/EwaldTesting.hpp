#pragma once
// Shared by the spectral Ewald tests: random points and densities, reference sums over a pair
// kernel, and the error measures.
#include <capsula/ewald/Ewald2PReference.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

namespace capsula::ewald::testing {

/// count points uniform over the cell [0, L_x) x [yLow, yHigh] x [0, L_z), 3 numbers each.
inline std::vector<double> randomPoints(const PeriodicLayer& box, int count, unsigned seed, double yLow, double yHigh)
{
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> points;
  for (int n = 0; n < count; ++n) {
    points.push_back(box.lengthX * unit(generator));
    points.push_back(yLow + (yHigh - yLow) * unit(generator));
    points.push_back(box.lengthZ * unit(generator));
  }
  return points;
}

/// Points in bands of heights [low, high]: count per band, uniform in x and z, band b from seed + b.
inline std::vector<double> pointsInBands(const PeriodicLayer& box, const std::vector<std::pair<double, double>>& bands,
                                         int count, unsigned seed)
{
  std::vector<double> points;
  for (const auto& [low, high] : bands) {
    const auto band = randomPoints(box, count, seed++, low, high);
    points.insert(points.end(), band.begin(), band.end());
  }
  return points;
}

/// count vectors of `components` numbers uniform in [-1, 1].
inline std::vector<double> randomForces(int count, unsigned seed, int components = 3)
{
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> component(-1.0, 1.0);
  std::vector<double> forces(static_cast<std::size_t>(components) * count);
  for (double& f : forces) {
    f = component(generator);
  }
  return forces;
}

/// max_t |u_t - v_t| / max_t |v_t| (the largest error relative to the largest velocity).
inline double relativeError(const std::vector<double>& u, const std::vector<double>& v)
{
  double error = 0.0, size = 0.0;
  for (std::size_t t = 0; t < u.size(); t += 3) {
    const double d = std::hypot(u[t] - v[t], u[t + 1] - v[t + 1], u[t + 2] - v[t + 2]);
    error = std::max(error, d);
    size = std::max(size, std::hypot(v[t], v[t + 1], v[t + 2]));
  }
  return error / size;
}

/// u_t = sum_n G(x_t, x_n) g_n, with pair(x_t, x_n, G) writing the 3 x 3 kernel of one pair
/// (3 numbers per point and per force): the reference sums the fast ones are tested against.
template <class Pair>
std::vector<double> pairSum(const std::vector<double>& sources, const std::vector<double>& forces,
                            const std::vector<double>& targets, const Pair& pair)
{
  std::vector<double> u(targets.size(), 0.0);
  for (std::size_t t = 0; t < targets.size(); t += 3) {
    for (std::size_t n = 0; n < sources.size(); n += 3) {
      double G[3][3];
      pair(&targets[t], &sources[n], G);
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          u[t + i] += G[i][j] * forces[n + j];
        }
      }
    }
  }
  return u;
}

/// The double layer u_t,j = sum_n T_ijk(x_n, x_t) S_n,ik, with stress(x_n, x_t, T) writing the
/// stress T[i][j][k] at x_n of a force along j at the pole x_t (tensors: 9 numbers per source,
/// S_ik at 9 n + 3 i + k): the reference the fast double layers are tested against.
template <class Stress>
std::vector<double> doubleLayerSum(const std::vector<double>& sources, const std::vector<double>& tensors,
                                   const std::vector<double>& targets, const Stress& stress)
{
  std::vector<double> u(targets.size(), 0.0);
  for (std::size_t t = 0; t < targets.size(); t += 3) {
    for (std::size_t n = 0; n < sources.size(); n += 3) {
      double T[3][3][3];
      stress(&sources[n], &targets[t], T);
      const double* S = &tensors[3 * n];
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          for (int k = 0; k < 3; ++k) {
            u[t + j] += T[i][j][k] * S[3 * i + k];
          }
        }
      }
    }
  }
  return u;
}

/// max_t |u_t| over the 3-vectors of u.
inline double largestSpeed(const std::vector<double>& u)
{
  double m = 0.0;
  for (std::size_t t = 0; t < u.size(); t += 3) {
    m = std::max(m, std::hypot(u[t], u[t + 1], u[t + 2]));
  }
  return m;
}

} // namespace capsula::ewald::testing
