#pragma once
// Point sets and reference sums shared by the treecode tests: random clouds, the
// quadrature points of spheres near the wall with their nodes as targets, and the direct
// regular sums of operators/RegularSums.hpp the treecode approximates.
#include <capsula/fastsum/Treecode.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/operators/CellSurfaces.hpp>
#include <capsula/operators/RegularSums.hpp>
#include <capsula/operators/SurfaceQuadrature.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace capsula::fastsum::testsets {

/// Sources with both layers' charges (structure of arrays) and targets (interleaved).
struct PointSet {
  std::vector<double> x, y, z;    // sources
  std::vector<double> fx, fy, fz; // single-layer charge
  std::vector<double> ax, ay, az; // weighted normal
  std::vector<double> vx, vy, vz; // double-layer density
  std::vector<double> targets;    // 3 per target
  int numSources() const { return static_cast<int>(x.size()); }
  int numTargets() const { return static_cast<int>(targets.size() / 3); }
};

inline void fillCharges(PointSet& s, std::mt19937& random)
{
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto n = s.x.size();
  for (auto* v : {&s.fx, &s.fy, &s.fz, &s.vx, &s.vy, &s.vz}) {
    v->resize(n);
    for (auto& value : *v) {
      value = unit(random);
    }
  }
  if (s.ax.size() != n) {
    for (auto* v : {&s.ax, &s.ay, &s.az}) {
      v->resize(n);
      for (auto& value : *v) {
        value = unit(random);
      }
    }
  }
}

/// n sources and m targets uniform in the box [0, 4] x [0.05, 2] x [0, 4] (above the wall).
inline PointSet randomCloud(int n, int m, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> across(0.0, 4.0), up(0.05, 2.0);
  PointSet s;
  for (int q = 0; q < n; ++q) {
    s.x.push_back(across(random));
    s.y.push_back(up(random));
    s.z.push_back(across(random));
  }
  for (int t = 0; t < m; ++t) {
    s.targets.insert(s.targets.end(), {across(random), up(random), across(random)});
  }
  fillCharges(s, random);
  return s;
}

/// Unit spheres at the given level in a row along x at height h above the wall, gap 0.2:
/// the sources are their N_Q = 7 quadrature points (a = n w h_s), the targets their nodes.
inline PointSet spheresNearWall(int numSpheres, int level, double h, unsigned seed)
{
  std::vector<mesh::SurfaceMesh> cells;
  for (int c = 0; c < numSpheres; ++c) {
    mesh::Placement placement;
    placement.centre = mesh::Vec3(2.2 * c, h, 0.0);
    cells.push_back(mesh::makeSphere(level, 1.0, placement));
  }
  const operators::CellSurfaces surfaces(std::move(cells), 1.0);
  operators::SurfaceQuadrature quadrature(7);
  quadrature.update(surfaces);
  const operators::QuadraturePoints& p = quadrature.points();
  PointSet s;
  s.x = p.x;
  s.y = p.y;
  s.z = p.z;
  s.ax = p.nx;
  s.ay = p.ny;
  s.az = p.nz;
  s.targets = quadrature.nodePositions();
  std::mt19937 random(seed);
  fillCharges(s, random);
  // A smooth load and density, as on a membrane, with noise of 10%: f = weight (1 + x/4)
  // e_y, v = (1 + x/4, 0.5, -0.3 z).
  for (int q = 0; q < s.numSources(); ++q) {
    s.fy[q] = p.weight[q] * (1.0 + 0.25 * s.x[q] + 0.1 * s.fy[q]);
    s.fx[q] *= 0.1 * p.weight[q];
    s.fz[q] *= 0.1 * p.weight[q];
    s.vx[q] = 1.0 + 0.25 * s.x[q] + 0.1 * s.vx[q];
    s.vy[q] = 0.5 + 0.1 * s.vy[q];
    s.vz[q] = -0.3 * s.z[q] + 0.1 * s.vz[q];
  }
  return s;
}

template <class Kernel, class Sum>
std::vector<double> directSums(const PointSet& s, const Sum& sum)
{
  const int m = s.numTargets();
  std::vector<double> u(3 * static_cast<std::size_t>(m));
  for (int first = 0; first < m; first += operators::targetBlockSize) {
    operators::TargetBlock block;
    block.start(std::min(operators::targetBlockSize, m - first));
    for (int k = 0; k < block.size; ++k) {
      block.x[k] = s.targets[3 * (first + k)];
      block.y[k] = s.targets[3 * (first + k) + 1];
      block.z[k] = s.targets[3 * (first + k) + 2];
    }
    block.pad();
    sum(block);
    for (int k = 0; k < block.size; ++k) {
      u[3 * (first + k)] = block.ux[k];
      u[3 * (first + k) + 1] = block.uy[k];
      u[3 * (first + k) + 2] = block.uz[k];
    }
  }
  return u;
}

/// The direct single-layer sums at the targets.
template <class Kernel>
std::vector<double> directSingleLayer(const PointSet& s)
{
  const operators::SingleLayerSources sources{s.x.data(),  s.y.data(),  s.z.data(),
                                              s.fx.data(), s.fy.data(), s.fz.data()};
  return directSums<Kernel>(s, [&](operators::TargetBlock& block) {
    operators::addSingleLayerSums<Kernel>(block, sources, 0, s.numSources());
  });
}

/// The direct double-layer sums at the targets.
template <class Kernel>
std::vector<double> directDoubleLayer(const PointSet& s)
{
  const operators::DoubleLayerSources sources{s.x.data(),  s.y.data(),  s.z.data(),  s.ax.data(), s.ay.data(),
                                              s.az.data(), s.vx.data(), s.vy.data(), s.vz.data()};
  return directSums<Kernel>(s, [&](operators::TargetBlock& block) {
    operators::addDoubleLayerSums<Kernel, false>(block, sources, 0, s.numSources());
  });
}

/// ||u - reference||_2 / ||reference||_2 (the error measure of Wang, Tlupova & Krasny).
inline double relativeError(const std::vector<double>& u, const std::vector<double>& reference)
{
  double difference = 0.0, norm = 0.0;
  for (std::size_t k = 0; k < u.size(); ++k) {
    difference += (u[k] - reference[k]) * (u[k] - reference[k]);
    norm += reference[k] * reference[k];
  }
  return std::sqrt(difference / norm);
}

/// The treecode's relative errors against the direct sums, both layers, and its proxy pairs.
struct LayerErrors {
  double single = 0.0;
  double dbl = 0.0;
  long long proxyPairs = 0;
};

template <class Kernel>
LayerErrors treecodeErrors(const PointSet& s, const TreecodeParameters& parameters)
{
  Treecode<Kernel> treecode(parameters);
  treecode.setSources(s.x.data(), s.y.data(), s.z.data(), s.numSources());
  treecode.setTargets(s.targets.data(), s.numTargets());
  std::vector<double> u(3 * static_cast<std::size_t>(s.numTargets()));
  LayerErrors errors;
  treecode.singleLayer(s.fx.data(), s.fy.data(), s.fz.data(), u.data());
  errors.single = relativeError(u, directSingleLayer<Kernel>(s));
  treecode.doubleLayer(s.ax.data(), s.ay.data(), s.az.data(), s.vx.data(), s.vy.data(), s.vz.data(), u.data());
  errors.dbl = relativeError(u, directDoubleLayer<Kernel>(s));
  errors.proxyPairs = treecode.interactionLists().proxyPairs;
  return errors;
}

} // namespace capsula::fastsum::testsets
