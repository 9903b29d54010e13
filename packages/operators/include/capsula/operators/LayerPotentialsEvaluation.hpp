#pragma once
// Part of LayerPotentials.hpp, included at its end: the layer potentials at the nodes and at
// points. The class and what it computes are described there.

namespace capsula::operators {

template <class Kernel>
void LayerPotentials<Kernel>::singleLayerOfNodalLoadAtNodes(const double* nodalLoad, double* result)
{
  prepareNodalSingleLayerCorrections();
  const QuadraturePoints& p = quadrature_.points();
  const int nq = quadrature_.pointsPerElement();
  fx_.resize(p.weight.size());
  fy_.resize(p.weight.size());
  fz_.resize(p.weight.size());
  for (int m = 0; m < quadrature_.numElements(); ++m) {
    const auto& nodes = quadrature_.elements().nodes[m];
    for (int k = 0; k < nq; ++k) {
      const std::size_t q = static_cast<std::size_t>(m) * nq + k;
      double f[3] = {0.0, 0.0, 0.0};
      for (int a = 0; a < 6; ++a) {
        const double phi = p.phi[6 * q + a];
        for (int i = 0; i < 3; ++i) {
          f[i] += phi * nodalLoad[3 * nodes[a] + i];
        }
      }
      fx_[q] = f[0] * p.weight[q];
      fy_[q] = f[1] * p.weight[q];
      fz_[q] = f[2] * p.weight[q];
    }
  }
  far_.resize(3 * static_cast<std::size_t>(numTargets_));
  farField_->singleLayer(singleLayerSources(), nodeTargets_.data(), numTargets_, far_.data());
  const auto blocks = detail::nodeBlocks(cells_, firstTarget_, numTargets_);
#if defined(_OPENMP)
#pragma omp parallel for schedule(dynamic)
#endif
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    for (int k = 0; k < blocks[b].count; ++k) {
      const int t = blocks[b].first + k;
      double u[3] = {far_[3 * t], far_[3 * t + 1], far_[3 * t + 2]};
      const TargetCorrections& corr = singleCorrections_[t];
      for (std::size_t e = 0; e < corr.nodes.size(); ++e) {
        detail::addTransposedProduct(&corr.dbl[9 * e], nodalLoad + 3 * corr.nodes[e], u);
      }
      for (int j = 0; j < 3; ++j) {
        result[3 * t + j] = u[j];
      }
    }
  }
}

template <class Kernel>
void LayerPotentials<Kernel>::buildSingleLayerSources(const LoadDensity& load)
{
  const QuadraturePoints& p = quadrature_.points();
  const int nq = quadrature_.pointsPerElement();
  const std::size_t n = p.weight.size();
  fx_.resize(n);
  fy_.resize(n);
  fz_.resize(n);
  for (int m = 0; m < quadrature_.numElements(); ++m) {
    const double* nodal = load.element(m);
    for (int k = 0; k < nq; ++k) {
      const std::size_t q = static_cast<std::size_t>(m) * nq + k;
      double f[3] = {0.0, 0.0, 0.0};
      for (int a = 0; a < 6; ++a) {
        const double phi = p.phi[6 * q + a];
        for (int i = 0; i < 3; ++i) {
          f[i] += phi * nodal[3 * a + i];
        }
      }
      fx_[q] = f[0] * p.weight[q];
      fy_[q] = f[1] * p.weight[q];
      fz_[q] = f[2] * p.weight[q];
    }
  }
}

template <class Kernel>
void LayerPotentials<Kernel>::buildDoubleLayerSources(const double* density)
{
  const QuadraturePoints& p = quadrature_.points();
  const int nq = quadrature_.pointsPerElement();
  const std::size_t n = p.weight.size();
  vx_.resize(n);
  vy_.resize(n);
  vz_.resize(n);
  for (int m = 0; m < quadrature_.numElements(); ++m) {
    const auto& nodes = quadrature_.elements().nodes[m];
    for (int k = 0; k < nq; ++k) {
      const std::size_t q = static_cast<std::size_t>(m) * nq + k;
      double v[3] = {0.0, 0.0, 0.0};
      for (int a = 0; a < 6; ++a) {
        const double phi = p.phi[6 * q + a];
        for (int i = 0; i < 3; ++i) {
          v[i] += phi * density[3 * nodes[a] + i];
        }
      }
      vx_[q] = v[0];
      vy_[q] = v[1];
      vz_[q] = v[2];
    }
  }
}

template <class Kernel>
SingleLayerSources LayerPotentials<Kernel>::singleLayerSources() const
{
  const QuadraturePoints& p = quadrature_.points();
  return {p.x.data(), p.y.data(), p.z.data(), fx_.data(), fy_.data(), fz_.data()};
}

template <class Kernel>
DoubleLayerSources LayerPotentials<Kernel>::doubleLayerSources() const
{
  const QuadraturePoints& p = quadrature_.points();
  return {p.x.data(),  p.y.data(), p.z.data(), p.nx.data(), p.ny.data(),
          p.nz.data(), vx_.data(), vy_.data(), vz_.data()};
}

template <class Kernel>
void LayerPotentials<Kernel>::singleLayerAtNodes(const LoadDensity& load, double* result)
{
  buildSingleLayerSources(load);
  findNodeNearElements();
  far_.resize(3 * static_cast<std::size_t>(numTargets_));
  farField_->singleLayer(singleLayerSources(), nodeTargets_.data(), numTargets_, far_.data());
  const double* positions = quadrature_.nodePositions().data();
  const auto blocks = detail::nodeBlocks(cells_, firstTarget_, numTargets_);
  long long nearCount = 0;
#if defined(_OPENMP)
#pragma omp parallel for schedule(dynamic) reduction(+ : nearCount)
#endif
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    ParametricRule rule;
    for (int k = 0; k < blocks[b].count; ++k) {
      const int t = blocks[b].first + k;
      const double* x0 = positions + 3 * (firstTarget_ + t);
      double u[3] = {far_[3 * t], far_[3 * t + 1], far_[3 * t + 2]};
      const auto add = [&u](const std::array<double, 3>& correction) {
        for (int j = 0; j < 3; ++j) {
          u[j] += correction[j];
        }
      };
      for (const auto& [m, localNode] : neighbourhoods_[t].incident) {
        add(singularCorrection(m, localNode, LoadedSingleLayerIntegrand<Kernel>{&kernel_, x0, load.element(m)}, rule));
      }
      const std::vector<int>& near = nodeNear_[t];
      nearCount += static_cast<long long>(near.size());
      for (const int m : near) {
        add(nearCorrection(m, LoadedSingleLayerIntegrand<Kernel>{&kernel_, x0, load.element(m)}));
      }
      for (int j = 0; j < 3; ++j) {
        result[3 * t + j] = u[j];
      }
    }
  }
  nearCount_ = nearCount;
}

template <class Kernel>
void LayerPotentials<Kernel>::doubleLayerAtNodes(const double* density, DoubleLayerForm form, double* result)
{
  prepareDoubleLayerCorrections();
  buildDoubleLayerSources(density);
  const bool subtract = form == DoubleLayerForm::Subtracted;
  far_.resize(3 * static_cast<std::size_t>(numTargets_));
  farField_->doubleLayer(doubleLayerSources(), nodeTargets_.data(), subtract ? nodeTargetCells_.data() : nullptr,
                         density + 3 * static_cast<std::size_t>(firstTarget_), numTargets_, far_.data());
  const auto blocks = detail::nodeBlocks(cells_, firstTarget_, numTargets_);
#if defined(_OPENMP)
#pragma omp parallel for schedule(dynamic)
#endif
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    for (int k = 0; k < blocks[b].count; ++k) {
      const int t = blocks[b].first + k;
      const double* u0 = density + 3 * (firstTarget_ + t);
      double u[3] = {far_[3 * t], far_[3 * t + 1], far_[3 * t + 2]};
      const TargetCorrections& corr = corrections_[t];
      for (std::size_t e = 0; e < corr.nodes.size(); ++e) {
        detail::addTransposedProduct(&corr.dbl[9 * e], density + 3 * corr.nodes[e], u);
      }
      if (subtract) {
        detail::addTransposedProduct(corr.self, u0, u);
        for (int j = 0; j < 3; ++j) {
          u[j] -= 4.0 * M_PI * u0[j];
        }
      }
      for (int j = 0; j < 3; ++j) {
        result[3 * t + j] = u[j];
      }
    }
  }
}

template <class Kernel>
int LayerPotentials<Kernel>::cellDoubleLayerBlock(int cell, std::vector<double>& block)
{
  prepareDoubleLayerCorrections();
  const CellRange& range = cells_[cell];
  const int first = std::max(range.firstNode, firstTarget_);
  const int end = std::min(range.endNode, firstTarget_ + numTargets_);
  const int rows = std::max(0, end - first);
  const int numNodes = range.endNode - range.firstNode;
  const std::size_t columns = 3 * static_cast<std::size_t>(numNodes);
  block.assign(3 * static_cast<std::size_t>(rows) * columns, 0.0);
  const double* positions = quadrature_.nodePositions().data();
  const QuadraturePoints& p = quadrature_.points();
  const int nq = quadrature_.pointsPerElement();
#if defined(_OPENMP)
#pragma omp parallel for schedule(dynamic, 4)
#endif
  for (int r = 0; r < rows; ++r) {
    const int g = first + r;
    const double* x0 = positions + 3 * g;
    // B_b, node b's 3x3 block (u_b,i B_ij adds to row j), node after node.
    std::vector<double> nodeBlocks(9 * static_cast<std::size_t>(numNodes), 0.0);
    const auto add = [&](int node, const double* B, double sign) {
      double* target = &nodeBlocks[9 * static_cast<std::size_t>(node - range.firstNode)];
      for (int k = 0; k < 9; ++k) {
        target[k] += sign * B[k];
      }
    };
    // The regular rule over the whole cell with the subtraction of u(x0) (eq 3.44), as the
    // far-field sums apply it to the own cell ...
    double subtracted[9] = {};
    for (int m = range.firstElement; m < range.endElement; ++m) {
      const auto& nodes = quadrature_.elements().nodes[m];
      for (int k = 0; k < nq; ++k) {
        const std::size_t q = static_cast<std::size_t>(m) * nq + k;
        const double x[3] = {p.x[q], p.y[q], p.z[q]};
        const double a[3] = {p.nx[q], p.ny[q], p.nz[q]};
        double Tn[9] = {};
        addDoubleLayerMatrix(kernel_, x, x0, a, Tn);
        for (int node = 0; node < 6; ++node) {
          add(nodes[node], Tn, p.phi[6 * q + node]);
        }
        detail::addScaledBlock(subtracted, Tn, 1.0);
      }
    }
    add(g, subtracted, -1.0);
    // ... the corrections on the cell's own nodes, and -4 pi u(x0).
    const TargetCorrections& corr = corrections_[g - firstTarget_];
    for (std::size_t e = 0; e < corr.nodes.size(); ++e) {
      if (corr.nodes[e] >= range.firstNode && corr.nodes[e] < range.endNode) {
        add(corr.nodes[e], &corr.dbl[9 * e], 1.0);
      }
    }
    add(g, corr.self, 1.0);
    const double identity[9] = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
    add(g, identity, -4.0 * M_PI);
    // Entry (3 r + j, 3 b + i) = (B_b)_ij.
    for (int j = 0; j < 3; ++j) {
      double* row = block.data() + (3 * static_cast<std::size_t>(r) + j) * columns;
      for (int b = 0; b < numNodes; ++b) {
        for (int i = 0; i < 3; ++i) {
          row[3 * b + i] = nodeBlocks[9 * static_cast<std::size_t>(b) + 3 * i + j];
        }
      }
    }
  }
  return rows;
}

template <class Kernel>
template <class AddNear>
void LayerPotentials<Kernel>::addNearCorrectionsAtPoints(const double* points, int n, const std::vector<double>& far,
                                                         double* result, const AddNear& addNear) const
{
#if defined(_OPENMP)
#pragma omp parallel for schedule(dynamic)
#endif
  for (int first = 0; first < n; first += targetBlockSize) {
    std::vector<int> near;
    for (int k = 0; k < std::min(targetBlockSize, n - first); ++k) {
      const double* x0 = points + 3 * (first + k);
      const double* sum = &far[3 * static_cast<std::size_t>(first + k)];
      double u[3] = {sum[0], sum[1], sum[2]};
      findNearElements(x0, nullptr, near);
      for (const int m : near) {
        addNear(m, x0, u);
      }
      for (int j = 0; j < 3; ++j) {
        result[3 * (first + k) + j] = u[j];
      }
    }
  }
}

template <class Kernel>
void LayerPotentials<Kernel>::singleLayerAtPoints(const double* points, int n, const LoadDensity& load, double* result)
{
  buildSingleLayerSources(load);
  std::vector<double> far(3 * static_cast<std::size_t>(n));
  farField_->singleLayer(singleLayerSources(), points, n, far.data());
  addNearCorrectionsAtPoints(points, n, far, result, [&](int m, const double* x0, double* u) {
    const auto correction = nearCorrection(m, LoadedSingleLayerIntegrand<Kernel>{&kernel_, x0, load.element(m)});
    for (int j = 0; j < 3; ++j) {
      u[j] += correction[j];
    }
  });
}

template <class Kernel>
void LayerPotentials<Kernel>::doubleLayerAtPoints(const double* points, int n, const double* density, double* result)
{
  buildDoubleLayerSources(density);
  std::vector<double> far(3 * static_cast<std::size_t>(n));
  farField_->doubleLayer(doubleLayerSources(), points, nullptr, nullptr, n, far.data());
  addNearCorrectionsAtPoints(points, n, far, result, [&](int m, const double* x0, double* u) {
    const auto correction = nearCorrection(m, DoubleLayerIntegrand<Kernel>{&kernel_, x0});
    const auto& nodes = quadrature_.elements().nodes[m];
    for (int a = 0; a < 6; ++a) {
      detail::addTransposedProduct(&correction[9 * a], density + 3 * nodes[a], u);
    }
  });
}

template <class Kernel>
void LayerPotentials<Kernel>::solidAnglesAtPoints(const double* points, int n, double* omega)
{
  const QuadraturePoints& p = quadrature_.points();
  const int nq = quadrature_.pointsPerElement();
  const int numCells = static_cast<int>(cells_.size());
#if defined(_OPENMP)
#pragma omp parallel for schedule(dynamic)
#endif
  for (int first = 0; first < n; first += targetBlockSize) {
    TargetBlock block;
    for (int c = 0; c < numCells; ++c) {
      startPointBlock(block, points, first, n, cellReach_[c].centre);
      addSolidAngleSums(block, p.x.data(), p.y.data(), p.z.data(), p.nx.data(), p.ny.data(), p.nz.data(),
                        cells_[c].firstElement * nq, cells_[c].endElement * nq);
      for (int k = 0; k < block.size; ++k) {
        omega[numCells * (first + k) + c] = block.ux[k];
      }
    }
    std::vector<int> near;
    for (int k = 0; k < block.size; ++k) {
      const double* x0 = points + 3 * (first + k);
      findNearElements(x0, nullptr, near);
      for (const int m : near) {
        int c = 0;
        while (m >= cells_[c].endElement) {
          ++c;
        }
        double centre[3], image[3];
        detail::elementCentre(quadrature_.elements(), m, centre);
        traits_.nearestImage(x0, centre, image);
        omega[numCells * (first + k) + c] += nearCorrection(m, SolidAngleIntegrand{image})[0];
      }
    }
  }
}

template <class Kernel>
void LayerPotentials<Kernel>::startPointBlock(TargetBlock& block, const double* points, int first, int n,
                                              const double* reference) const
{
  block.start(std::min(targetBlockSize, n - first));
  for (int k = 0; k < block.size; ++k) {
    double image[3];
    traits_.nearestImage(points + 3 * (first + k), reference, image);
    block.x[k] = image[0];
    block.y[k] = image[1];
    block.z[k] = image[2];
  }
  block.pad();
}

} // namespace capsula::operators
