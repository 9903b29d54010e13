#pragma once
// Part of LayerPotentials.hpp, included at its end: the element rules and the singular and
// near-singular corrections. The class and what it computes are described there.

namespace capsula::operators {

namespace detail {

// Moves the `keep` poles closest to `centre` to the front of poles[0 .. numPoles).
template <std::size_t N>
void keepClosestPoles(double (&poles)[N][3], int numPoles, const double* centre, int keep)
{
  const auto distance2 = [centre](const double* p) {
    const double dx = p[0] - centre[0], dy = p[1] - centre[1], dz = p[2] - centre[2];
    return dx * dx + dy * dy + dz * dz;
  };
  for (int k = 0; k < keep && k < numPoles; ++k) {
    int best = k;
    for (int p = k + 1; p < numPoles; ++p) {
      if (distance2(poles[p]) < distance2(poles[best])) {
        best = p;
      }
    }
    for (int i = 0; i < 3; ++i) {
      std::swap(poles[k][i], poles[best][i]);
    }
  }
}

} // namespace detail

template <class Kernel>
template <class Integrand>
typename Integrand::Value LayerPotentials<Kernel>::regularRule(int m, const Integrand& integrand) const
{
  const QuadraturePoints& p = quadrature_.points();
  typename Integrand::Value sum{}, term;
  const int nq = quadrature_.pointsPerElement();
  for (int k = 0; k < nq; ++k) {
    const std::size_t q = static_cast<std::size_t>(m) * nq + k;
    ElementSample s;
    s.x[0] = p.x[q];
    s.x[1] = p.y[q];
    s.x[2] = p.z[q];
    s.weight = p.weight[q];
    s.weightedNormal[0] = p.nx[q];
    s.weightedNormal[1] = p.ny[q];
    s.weightedNormal[2] = p.nz[q];
    std::copy(&p.phi[6 * q], &p.phi[6 * q] + 6, s.phi);
    integrand.evaluate(s, term);
    for (int c = 0; c < Integrand::size; ++c) {
      sum[c] += term[c];
    }
  }
  return sum;
}

template <class Kernel>
template <class Integrand>
typename Integrand::Value LayerPotentials<Kernel>::nearCorrection(int m, const Integrand& integrand) const
{
  const ElementMap& element = elementMaps_[m];
  // The poles next to the element: the target's image nearest to it (the target itself
  // unless the kernel is periodic) and that image's images; where there are more than the
  // subdivision takes, the closest to the element.
  double poles[KernelTraits<Kernel>::maxImages + 1][3];
  double centre[3];
  detail::elementCentre(quadrature_.elements(), m, centre);
  traits_.nearestImage(integrand.x0, centre, poles[0]);
  int numPoles = 1 + traits_.images(poles[0], poles + 1);
  if (numPoles > maxPoles) {
    detail::keepClosestPoles(poles, numPoles, centre, maxPoles);
    numPoles = maxPoles;
  }
  auto value = AdaptiveElementQuadrature<Integrand>(element, integrand, quadrature_.rule(),
                                                    parameters_.nearSingularTolerance, poles, numPoles)
                   .integrate();
  const auto regular = regularRule(m, integrand);
  for (int c = 0; c < Integrand::size; ++c) {
    value[c] -= regular[c];
  }
  return value;
}

template <class Kernel>
template <class Integrand>
typename Integrand::Value LayerPotentials<Kernel>::singularCorrection(int m, int localNode, const Integrand& integrand,
                                                                      ParametricRule& rule) const
{
  const ElementMap& element = elementMaps_[m];
  // The vertex rules do not depend on the element; the midside ones do (alpha, beta, gamma).
  const ParametricRule* polar = &vertexRules_[std::min(localNode, 2)];
  if (localNode >= 3) {
    singularRule(localNode, element.shape(), gauss_, rule);
    polar = &rule;
  }
  auto value = integrateWithRule(element, integrand, *polar);
  const auto regular = regularRule(m, integrand);
  for (int c = 0; c < Integrand::size; ++c) {
    value[c] -= regular[c];
  }
  return value;
}

template <class Kernel>
void LayerPotentials<Kernel>::findNodeNearElements()
{
  if (hasNodeNear_) {
    return;
  }
  nodeNear_.resize(static_cast<std::size_t>(numTargets_));
  const double* positions = quadrature_.nodePositions().data();
#if defined(_OPENMP)
#pragma omp parallel for schedule(dynamic, 16)
#endif
  for (int t = 0; t < numTargets_; ++t) {
    findNearElements(positions + 3 * (firstTarget_ + t), &neighbourhoods_[t], nodeNear_[t]);
  }
  hasNodeNear_ = true;
}

// Corrections of target t as node blocks: sum_a u_a . D_a over every singular and
// near-singular element, D_a = special - regular of int phi_a T n dS (double layer) or of
// int phi_a G dS (nodal single layer), and for the double layer's own cell the
// subtraction's block -sum_a D_a on u(x0).
template <class Kernel>
template <class Integrand>
void LayerPotentials<Kernel>::correctTarget(int t, const Integrand& integrand, bool subtractOwn, TargetCorrections& out,
                                            ParametricRule& rule) const
{
  const CellRange& own = cells_[cellOfNode(firstTarget_ + t)];
  const auto record = [&](int m, const typename Integrand::Value& correction) {
    const bool subtract = subtractOwn && m >= own.firstElement && m < own.endElement;
    const auto& nodes = quadrature_.elements().nodes[m];
    for (int a = 0; a < 6; ++a) {
      const double* block = &correction[9 * a];
      const auto found = std::find(out.nodes.begin(), out.nodes.end(), nodes[a]);
      if (found == out.nodes.end()) {
        out.nodes.push_back(nodes[a]);
        out.dbl.insert(out.dbl.end(), block, block + 9);
      } else {
        detail::addScaledBlock(&out.dbl[9 * (found - out.nodes.begin())], block, 1.0);
      }
      if (subtract) {
        detail::addScaledBlock(out.self, block, -1.0);
      }
    }
  };
  for (const auto& [m, localNode] : neighbourhoods_[t].incident) {
    record(m, singularCorrection(m, localNode, integrand, rule));
  }
  for (const int m : nodeNear_[t]) {
    record(m, nearCorrection(m, integrand));
  }
}

template <class Kernel>
template <class Integrand>
void LayerPotentials<Kernel>::prepareCorrections(bool subtractOwn, std::vector<TargetCorrections>& corrections)
{
  findNodeNearElements();
  corrections.assign(numTargets_, TargetCorrections{});
  const double* positions = quadrature_.nodePositions().data();
#if defined(_OPENMP)
#pragma omp parallel
#endif
  {
    ParametricRule rule;
#if defined(_OPENMP)
#pragma omp for schedule(dynamic, 16)
#endif
    for (int t = 0; t < numTargets_; ++t) {
      correctTarget(t, Integrand{&kernel_, positions + 3 * (firstTarget_ + t)}, subtractOwn, corrections[t], rule);
    }
  }
}

template <class Kernel>
void LayerPotentials<Kernel>::prepareDoubleLayerCorrections()
{
  if (!hasDoubleCorrections_) {
    prepareCorrections<DoubleLayerIntegrand<Kernel>>(/*subtractOwn=*/true, corrections_);
    hasDoubleCorrections_ = true;
  }
}

template <class Kernel>
void LayerPotentials<Kernel>::prepareNodalSingleLayerCorrections()
{
  if (!hasSingleCorrections_) {
    prepareCorrections<NodalSingleLayerIntegrand<Kernel>>(/*subtractOwn=*/false, singleCorrections_);
    hasSingleCorrections_ = true;
  }
}

} // namespace capsula::operators
