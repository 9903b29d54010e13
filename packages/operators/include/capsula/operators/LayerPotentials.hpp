#pragma once
// (Length: one class template per Green's function, instantiated in BuiltInKernels.cpp; the
// regular sums, the singular and near-singular corrections and the geometry they share are
// members that the hot loops inline across, so they stay in one header.)
//
// The single- and double-layer integrals of eq 3.38 for one Green's function (a kernel
// policy, KernelTraits.hpp), on the nodes this rank owns and at arbitrary points.
//
// For a target x0 every element is integrated in one of three ways:
//   regular        the N_Q-point rule (eq 3.39), in the vectorised sums of RegularSums.hpp;
//   singular       x0 is a node of the element: polar coordinates around it (eqs 3.42-3.43);
//   near-singular  x0 (or an image of it, for the wall) is within `Near-singular distance`
//                  element sizes of the element's bounding sphere: adaptive subdivision
//                  (AdaptiveQuadrature.hpp).
// The sums run over ALL points (no branch in the hot loop); the singular and
// near-singular elements then get a correction "special rule minus regular rule". The
// sums go through a FarFieldSummation back-end (FarFieldSummation.hpp): DirectSummation by
// default, or a fast one (a treecode), which then approximates the regular rule only; the
// corrections stay exact.
// A node's own neighbourhood (`Regular neighbour rings` of elements around those holding
// it, 2 by default) is left to the regular rule, as in the thesis: there the target lies
// in the tangent plane of a smooth surface, where the rule is 10-50 times more accurate
// than at the same distance off the surface, and subdividing changes the velocity by less
// than the discretisation error (docs/operators.md). The same elements seen from the
// images, and every farther element of the cell (a cell folding onto itself), are tested
// as usual.
// The single-layer corrections are computed with the load at each evaluation, except for
// a load given at the nodes (singleLayerOfNodalLoadAtNodes, the repeated applications of
// a stiff time step's linear solve), whose corrections are node blocks like the double
// layer's; the double-layer ones are 3x3 blocks on nodes, built once per geometry and
// reused by every application of the GMRES solve. Which elements are near each node target is found once
// per geometry and shared by both layers.
//
// Double layer on a surface (thesis eq 3.44 with the ERRATA sign): with n outward and
// T_ijk = -6 xh_i xh_j xh_k / r^5, PV int_S T_ijk n_k dS = -4 pi delta_ij at a point of a
// smooth surface S, so for x0 on cell c
//   PV int_Sc u_i T_ijk n_k dS = int_Sc [u_i(x) - u_i(x0)] T_ijk n_k dS - 4 pi u_j(x0),
// which holds for the wall kernel too (a closed surface in the fluid). Other cells are
// integrated directly (x0 is outside them: the identity gives 0).
#include <capsula/operators/AdaptiveQuadrature.hpp>
#include <capsula/operators/CellSurfaces.hpp>
#include <capsula/operators/DoubleLayerForm.hpp>
#include <capsula/operators/DirectSummation.hpp>
#include <capsula/operators/ElementIntegrals.hpp>
#include <capsula/operators/FarFieldBackEnd.hpp>
#include <capsula/operators/FarFieldSummation.hpp>
#include <capsula/operators/KernelTraits.hpp>
#include <capsula/operators/LoadDensity.hpp>
#include <capsula/operators/OperatorParameters.hpp>
#include <capsula/operators/PolarRules.hpp>
#include <capsula/operators/RegularSums.hpp>
#include <capsula/operators/SurfaceQuadrature.hpp>

#include <capsula/core/Error.hpp>
#include <capsula/quadrature/GaussLegendre.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <typeinfo>
#include <vector>

namespace capsula::operators {

template <class Kernel>
class LayerPotentials {
public:
  /// The regular sums go to the back-end of parameters.farField (DirectSummation<Kernel>
  /// when null); throws core::InputError naming 'Operator/Summation' if it does not
  /// support Kernel.
  explicit LayerPotentials(const DiscretisationParameters& parameters);

  /// Sets the node targets, the global nodes [firstTargetNode, firstTargetNode +
  /// numTargetNodes) (the rows this rank owns), and the topology of `surfaces`, then
  /// calls update(surfaces).
  void setTopology(const CellSurfaces& surfaces, int firstTargetNode, int numTargetNodes);

  /// Rebuilds the quadrature caches from the current positions of `surfaces` (the
  /// topology given to setTopology) and drops the node corrections.
  void update(const CellSurfaces& surfaces);

  const SurfaceQuadrature& quadrature() const { return quadrature_; }
  const DiscretisationParameters& parameters() const { return parameters_; }
  const FarFieldSummation& farField() const { return *farField_; }
  int firstTargetNode() const { return firstTarget_; }
  int numTargetNodes() const { return numTargets_; }

  /// Builds the singular and near-singular corrections of the double layer at the node
  /// targets (doubleLayerAtNodes calls it when needed).
  void prepareDoubleLayerCorrections();

  /// result[3 t + j] = sum_m int_Em Delta f_i G_ij(x, x_t) dS (eq 3.36) at the target
  /// nodes, Delta f interpolated from its values at the element nodes (LoadDensity.hpp).
  void singleLayerAtNodes(const LoadDensity& load, double* result);

  /// The same for a load continuous across the elements, given by its values at the nodes
  /// (3 per node, global numbering). The singular and near-singular corrections are node
  /// blocks built on the first call after update() and reused until the next (the result
  /// agrees with singleLayerAtNodes to the near-singular tolerance).
  void singleLayerOfNodalLoadAtNodes(const double* nodalLoad, double* result);

  /// result[3 t + j] = sum over all cells of PV int u_i T_ijk(x, x_t) n_k dS at the target
  /// nodes, for the density u given at every node (3 per node, global numbering) and
  /// interpolated over each element with its shape functions.
  void doubleLayerAtNodes(const double* density, DoubleLayerForm form, double* result);

  /// The single layer at n arbitrary points (3 each) off the surfaces (a point on a
  /// surface gets the subdivision down to its depth limit and a meaningless value).
  void singleLayerAtPoints(const double* points, int n, const LoadDensity& load, double* result);

  /// The double layer at n arbitrary points off the surfaces.
  void doubleLayerAtPoints(const double* points, int n, const double* density, double* result);

  /// omega[numCells() p + c]: the solid angle of cell c seen from point p (4 pi inside,
  /// 0 outside).
  void solidAnglesAtPoints(const double* points, int n, double* omega);

  /// Near-singular (target, element) pairs of the last node evaluation (diagnostics).
  long long nearSingularElementCount() const { return nearCount_; }

private:
  struct TargetCorrections {
    std::vector<int> nodes;  // node b ...
    std::vector<double> dbl; // ... and its block: result_j += u_b,i B_ij, [9 k + 3 i + j]
    double self[9] = {};     // the subtraction's block on u(x0), own cell only
  };

  // A node target's neighbourhood on its own cell: the elements holding it, and those
  // within parameters_.regularNeighbourRings rings of them (sharing a node, ring after ring).
  struct Neighbourhood {
    std::vector<std::pair<int, int>> incident; // (element, local node of the target)
    std::vector<int> ring;                     // sorted; includes the incident elements
  };

  struct CellRange {
    int firstNode, endNode, firstElement, endElement;
  };

  // A sphere about a cell that holds every element's near-singular zone (bounding sphere
  // plus `Near-singular distance` sizes): a target outside it, and its images too, is near
  // none of the cell's elements, which findNearElements then skips without testing them.
  struct CellReach {
    double centre[3];
    double radius;
  };

  int cellOfNode(int node) const;
  // Elements near x0 or one of its images; for a node target (neighbourhood given) its
  // incident elements are left out and its ring is tested from the images only.
  void findNearElements(const double* x0, const Neighbourhood* neighbourhood, std::vector<int>& near) const;
  // The elements [begin, end) near one of the poles (x0 and its images), appended to near.
  void addNearElements(const double (*poles)[3], int numPoles, int begin, int end, const Neighbourhood* neighbourhood,
                       std::vector<int>& near) const;
  // The regular rule over element m, as the sums do it, for one integrand.
  template <class Integrand>
  typename Integrand::Value regularRule(int m, const Integrand& integrand) const;
  // special - regular over element m for the target of `integrand`.
  template <class Integrand>
  typename Integrand::Value nearCorrection(int m, const Integrand& integrand) const;
  template <class Integrand>
  typename Integrand::Value singularCorrection(int m, int localNode, const Integrand& integrand,
                                               ParametricRule& rule) const;
  void correctDoubleLayer(int target, TargetCorrections& out, ParametricRule& rule) const;
  void correctNodalSingleLayer(int target, TargetCorrections& out, ParametricRule& rule) const;
  void prepareNodalSingleLayerCorrections();
  // The near elements of every node target for the current geometry (findNearElements
  // with the target's neighbourhood), found on first use after update().
  void findNodeNearElements();
  void buildSingleLayerSources(const LoadDensity& load);
  void buildDoubleLayerSources(const double* density);
  SingleLayerSources singleLayerSources() const;
  DoubleLayerSources doubleLayerSources() const;
  static void startPointBlock(TargetBlock& block, const double* points, int first, int n);

  DiscretisationParameters parameters_;
  SurfaceQuadrature quadrature_;
  std::vector<ElementMap> elementMaps_; // per element, for the special rules
  quadrature::Rule1D gauss_;
  ParametricRule vertexRules_[3];
  std::vector<CellRange> cells_;
  std::vector<CellReach> cellReach_;          // per cell, for the current geometry
  std::vector<Neighbourhood> neighbourhoods_; // per node target
  int firstTarget_ = 0;
  int numTargets_ = 0;

  bool hasDoubleCorrections_ = false;
  std::vector<TargetCorrections> corrections_;
  bool hasSingleCorrections_ = false;
  std::vector<TargetCorrections> singleCorrections_; // nodal loads; .self unused
  bool hasNodeNear_ = false;
  std::vector<std::vector<int>> nodeNear_; // per node target
  long long nearCount_ = 0;

  // Per-evaluation source arrays (kept to avoid reallocation).
  std::vector<double> fx_, fy_, fz_, vx_, vy_, vz_;

  std::unique_ptr<FarFieldSummation> farField_;
  std::vector<double> nodeTargets_;  // positions of the target nodes (3 each)
  std::vector<int> nodeTargetCells_; // their cells
  std::vector<double> far_;          // the back-end's sums (3 per target)
};

// ---------------------------------------------------------------------------------------
// Implementation

namespace detail {

inline void addScaledBlock(double* block, const double* values, double scale)
{
  for (int k = 0; k < 9; ++k) {
    block[k] += scale * values[k];
  }
}

// result_j += sum_i v_i B_ij
inline void addTransposedProduct(const double* B, const double* v, double* result)
{
  for (int j = 0; j < 3; ++j) {
    result[j] += v[0] * B[j] + v[1] * B[3 + j] + v[2] * B[6 + j];
  }
}

// Blocks of at most targetBlockSize consecutive node targets that never straddle a cell.
struct NodeBlock {
  int cell, first, count; // first: target index (0-based in the owned range)
};

template <class CellRanges>
std::vector<NodeBlock> nodeBlocks(const CellRanges& cells, int firstTarget, int numTargets)
{
  std::vector<NodeBlock> blocks;
  for (int c = 0; c < static_cast<int>(cells.size()); ++c) {
    const int begin = std::max(cells[c].firstNode, firstTarget);
    const int end = std::min(cells[c].endNode, firstTarget + numTargets);
    for (int g = begin; g < end; g += targetBlockSize) {
      blocks.push_back({c, g - firstTarget, std::min(targetBlockSize, end - g)});
    }
  }
  return blocks;
}

} // namespace detail

template <class Kernel>
LayerPotentials<Kernel>::LayerPotentials(const DiscretisationParameters& parameters)
    : parameters_(parameters),
      quadrature_(parameters.quadraturePoints),
      gauss_(quadrature::gaussLegendre(parameters.singularQuadraturePoints, 0.0, 1.0))
{
  if (parameters.farField) {
    farField_ = parameters.farField->forKernel(typeid(Kernel), Kernel::name);
    core::require<core::InputError>(farField_ != nullptr, "'Operator/Summation' = ", parameters.farField->name(),
                                    " does not support the ", Kernel::name,
                                    " kernel ('Operator/Kernel'); use 'Operator/Summation' = Direct or another "
                                    "kernel.");
  } else {
    farField_ = std::make_unique<DirectSummation<Kernel>>();
  }
  validate(parameters_);
  for (int vertex = 0; vertex < 3; ++vertex) {
    singularRule(vertex, mesh::ShapeParameters{}, gauss_, vertexRules_[vertex]);
  }
}

template <class Kernel>
void LayerPotentials<Kernel>::setTopology(const CellSurfaces& surfaces, int firstTargetNode, int numTargetNodes)
{
  core::require<core::InputError>(firstTargetNode >= 0 && numTargetNodes >= 0 &&
                                      firstTargetNode + numTargetNodes <= surfaces.numNodes(),
                                  "The target nodes [", firstTargetNode, ", ", firstTargetNode + numTargetNodes,
                                  ") are not nodes of the ", surfaces.numNodes(), "-node scene.");
  cells_.clear();
  for (int c = 0; c < surfaces.numCells(); ++c) {
    cells_.push_back({surfaces.nodeOffset(c), surfaces.nodeOffset(c) + surfaces.cell(c).numNodes(),
                      surfaces.elementOffset(c), surfaces.elementOffset(c) + surfaces.cell(c).numElements()});
  }
  firstTarget_ = firstTargetNode;
  numTargets_ = numTargetNodes;
  neighbourhoods_.assign(numTargets_, {});
  for (int t = 0; t < numTargets_; ++t) {
    const int g = firstTarget_ + t;
    const int c = cellOfNode(g);
    const mesh::SurfaceMesh& cell = surfaces.cell(c);
    Neighbourhood& hood = neighbourhoods_[t];
    // Local element numbers: the incident elements, then rings of neighbours.
    std::vector<int> ring;
    for (const auto& touch : cell.incidentElements(g - cells_[c].firstNode)) {
      hood.incident.emplace_back(cells_[c].firstElement + touch.element, touch.localNode);
      ring.push_back(touch.element);
    }
    for (int layer = 0; layer < parameters_.regularNeighbourRings; ++layer) {
      const std::size_t inner = ring.size();
      for (std::size_t k = 0; k < inner; ++k) {
        for (const int node : cell.element(ring[k])) {
          for (const auto& next : cell.incidentElements(node)) {
            ring.push_back(next.element);
          }
        }
      }
      std::sort(ring.begin(), ring.end());
      ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    }
    std::sort(ring.begin(), ring.end());
    for (const int e : ring) {
      hood.ring.push_back(cells_[c].firstElement + e);
    }
  }
  update(surfaces);
}

template <class Kernel>
void LayerPotentials<Kernel>::update(const CellSurfaces& surfaces)
{
  core::require(!cells_.empty() && surfaces.numCells() == static_cast<int>(cells_.size()) &&
                    surfaces.numNodes() == cells_.back().endNode && surfaces.numElements() == cells_.back().endElement,
                "LayerPotentials::update: call setTopology first, with the same surfaces.");
  quadrature_.update(surfaces);
  elementMaps_.clear();
  elementMaps_.reserve(quadrature_.numElements());
  for (int m = 0; m < quadrature_.numElements(); ++m) {
    elementMaps_.emplace_back(quadrature_.elementNodes(m), quadrature_.elements().shape[m]);
  }
  const double* positions = quadrature_.nodePositions().data();
  for (int g = 0; g < surfaces.numNodes(); ++g) {
    core::require<core::InputError>(KernelTraits<Kernel>::inFluid(positions + 3 * g), "Node ", g,
                                    " of the scene lies outside the fluid domain of the ", Kernel::name, " kernel (at ",
                                    positions[3 * g], ", ", positions[3 * g + 1], ", ", positions[3 * g + 2], ").");
  }
  const ElementData& elements = quadrature_.elements();
  cellReach_.clear();
  for (const CellRange& cell : cells_) {
    CellReach reach{{0.0, 0.0, 0.0}, 0.0};
    const double count = cell.endElement - cell.firstElement;
    for (int m = cell.firstElement; m < cell.endElement; ++m) {
      reach.centre[0] += elements.cx[m] / count;
      reach.centre[1] += elements.cy[m] / count;
      reach.centre[2] += elements.cz[m] / count;
    }
    for (int m = cell.firstElement; m < cell.endElement; ++m) {
      const double dx = elements.cx[m] - reach.centre[0], dy = elements.cy[m] - reach.centre[1],
                   dz = elements.cz[m] - reach.centre[2];
      reach.radius = std::max(reach.radius, std::sqrt(dx * dx + dy * dy + dz * dz) + elements.radius[m] +
                                                parameters_.nearSingularDistance * elements.size[m]);
    }
    reach.radius *= 1.0 + 1e-9; // round-off: never skip an element the element test would keep
    cellReach_.push_back(reach);
  }
  const int nq = quadrature_.pointsPerElement();
  std::vector<int> cellPointOffsets{0};
  for (const CellRange& cell : cells_) {
    cellPointOffsets.push_back(cell.endElement * nq);
  }
  const QuadraturePoints& points = quadrature_.points();
  farField_->setSources(points.x.data(), points.y.data(), points.z.data(), cellPointOffsets);
  nodeTargets_.assign(positions + 3 * static_cast<std::size_t>(firstTarget_),
                      positions + 3 * static_cast<std::size_t>(firstTarget_ + numTargets_));
  nodeTargetCells_.resize(numTargets_);
  for (int t = 0; t < numTargets_; ++t) {
    nodeTargetCells_[t] = cellOfNode(firstTarget_ + t);
  }
  hasDoubleCorrections_ = false;
  corrections_.clear();
  hasSingleCorrections_ = false;
  singleCorrections_.clear();
  hasNodeNear_ = false;
}

template <class Kernel>
int LayerPotentials<Kernel>::cellOfNode(int node) const
{
  int c = 0;
  while (node >= cells_[c].endNode) {
    ++c;
  }
  return c;
}

template <class Kernel>
void LayerPotentials<Kernel>::findNearElements(const double* x0, const Neighbourhood* neighbourhood,
                                               std::vector<int>& near) const
{
  near.clear();
  const double reach = parameters_.nearSingularDistance;
  if (reach <= 0.0 || KernelTraits<Kernel>::vanishesAt(x0)) {
    return;
  }
  double poles[KernelTraits<Kernel>::maxImages + 1][3];
  for (int i = 0; i < 3; ++i) {
    poles[0][i] = x0[i];
  }
  const int numPoles = 1 + KernelTraits<Kernel>::images(x0, poles + 1);
  for (std::size_t c = 0; c < cells_.size(); ++c) {
    const CellReach& cell = cellReach_[c];
    bool reached = false;
    for (int p = 0; p < numPoles; ++p) {
      const double dx = poles[p][0] - cell.centre[0], dy = poles[p][1] - cell.centre[1],
                   dz = poles[p][2] - cell.centre[2];
      reached = reached || dx * dx + dy * dy + dz * dz < cell.radius * cell.radius;
    }
    if (reached) {
      addNearElements(poles, numPoles, cells_[c].firstElement, cells_[c].endElement, neighbourhood, near);
    }
  }
}

template <class Kernel>
void LayerPotentials<Kernel>::addNearElements(const double (*poles)[3], int numPoles, int begin, int end,
                                              const Neighbourhood* neighbourhood, std::vector<int>& near) const
{
  const double reach = parameters_.nearSingularDistance;
  const ElementData& e = quadrature_.elements();
  // Fast path: one branch-free pass over the bounding spheres, then the few close ones.
  for (int m = begin; m < end; ++m) {
    const double limit = e.radius[m] + reach * e.size[m];
    double closest = std::numeric_limits<double>::infinity();
    for (int p = 0; p < numPoles; ++p) {
      const double dx = poles[p][0] - e.cx[m], dy = poles[p][1] - e.cy[m], dz = poles[p][2] - e.cz[m];
      closest = std::min(closest, dx * dx + dy * dy + dz * dz - limit * limit);
    }
    if (closest >= 0.0) {
      continue;
    }
    if (neighbourhood) {
      // Incident: singular. Ring: the N_Q rule unless an image is close.
      const auto& ring = neighbourhood->ring;
      if (std::binary_search(ring.begin(), ring.end(), m)) {
        const bool incident = std::any_of(neighbourhood->incident.begin(), neighbourhood->incident.end(),
                                          [m](const auto& touch) { return touch.first == m; });
        bool imageClose = false;
        for (int p = 1; p < numPoles; ++p) {
          const double dx = poles[p][0] - e.cx[m], dy = poles[p][1] - e.cy[m], dz = poles[p][2] - e.cz[m];
          imageClose = imageClose || dx * dx + dy * dy + dz * dz < limit * limit;
        }
        if (incident || !imageClose) {
          continue;
        }
      }
    }
    near.push_back(m);
  }
}

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
  double poles[KernelTraits<Kernel>::maxImages + 1][3];
  for (int i = 0; i < 3; ++i) {
    poles[0][i] = integrand.x0[i];
  }
  const int numPoles = 1 + KernelTraits<Kernel>::images(integrand.x0, poles + 1);
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

// Double-layer corrections of target t as node blocks: sum_a u_a . D_a over every
// singular and near-singular element, D_a = special - regular of int phi_a T n dS, and
// for the own cell the subtraction's block -sum_a D_a on u(x0).
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

template <class Kernel>
void LayerPotentials<Kernel>::correctDoubleLayer(int t, TargetCorrections& out, ParametricRule& rule) const
{
  const double* x0 = quadrature_.nodePositions().data() + 3 * (firstTarget_ + t);
  const DoubleLayerIntegrand<Kernel> integrand{x0};
  const CellRange& own = cells_[cellOfNode(firstTarget_ + t)];
  const auto record = [&](int m, const typename DoubleLayerIntegrand<Kernel>::Value& correction) {
    const bool ownCell = m >= own.firstElement && m < own.endElement;
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
      if (ownCell) {
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
void LayerPotentials<Kernel>::prepareDoubleLayerCorrections()
{
  if (hasDoubleCorrections_) {
    return;
  }
  findNodeNearElements();
  corrections_.assign(numTargets_, TargetCorrections{});
#if defined(_OPENMP)
#pragma omp parallel
#endif
  {
    ParametricRule rule;
#if defined(_OPENMP)
#pragma omp for schedule(dynamic, 16)
#endif
    for (int t = 0; t < numTargets_; ++t) {
      correctDoubleLayer(t, corrections_[t], rule);
    }
  }
  hasDoubleCorrections_ = true;
}

template <class Kernel>
void LayerPotentials<Kernel>::correctNodalSingleLayer(int t, TargetCorrections& out, ParametricRule& rule) const
{
  const double* x0 = quadrature_.nodePositions().data() + 3 * (firstTarget_ + t);
  const NodalSingleLayerIntegrand<Kernel> integrand{x0};
  const auto record = [&](int m, const typename NodalSingleLayerIntegrand<Kernel>::Value& correction) {
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
void LayerPotentials<Kernel>::prepareNodalSingleLayerCorrections()
{
  if (hasSingleCorrections_) {
    return;
  }
  findNodeNearElements();
  singleCorrections_.assign(numTargets_, TargetCorrections{});
#if defined(_OPENMP)
#pragma omp parallel
#endif
  {
    ParametricRule rule;
#if defined(_OPENMP)
#pragma omp for schedule(dynamic, 16)
#endif
    for (int t = 0; t < numTargets_; ++t) {
      correctNodalSingleLayer(t, singleCorrections_[t], rule);
    }
  }
  hasSingleCorrections_ = true;
}

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
        add(singularCorrection(m, localNode, LoadedSingleLayerIntegrand<Kernel>{x0, load.element(m)}, rule));
      }
      const std::vector<int>& near = nodeNear_[t];
      nearCount += static_cast<long long>(near.size());
      for (const int m : near) {
        add(nearCorrection(m, LoadedSingleLayerIntegrand<Kernel>{x0, load.element(m)}));
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
void LayerPotentials<Kernel>::singleLayerAtPoints(const double* points, int n, const LoadDensity& load, double* result)
{
  buildSingleLayerSources(load);
  std::vector<double> far(3 * static_cast<std::size_t>(n));
  farField_->singleLayer(singleLayerSources(), points, n, far.data());
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
        const auto correction = nearCorrection(m, LoadedSingleLayerIntegrand<Kernel>{x0, load.element(m)});
        for (int j = 0; j < 3; ++j) {
          u[j] += correction[j];
        }
      }
      for (int j = 0; j < 3; ++j) {
        result[3 * (first + k) + j] = u[j];
      }
    }
  }
}

template <class Kernel>
void LayerPotentials<Kernel>::doubleLayerAtPoints(const double* points, int n, const double* density, double* result)
{
  buildDoubleLayerSources(density);
  std::vector<double> far(3 * static_cast<std::size_t>(n));
  farField_->doubleLayer(doubleLayerSources(), points, nullptr, nullptr, n, far.data());
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
        const auto correction = nearCorrection(m, DoubleLayerIntegrand<Kernel>{x0});
        const auto& nodes = quadrature_.elements().nodes[m];
        for (int a = 0; a < 6; ++a) {
          detail::addTransposedProduct(&correction[9 * a], density + 3 * nodes[a], u);
        }
      }
      for (int j = 0; j < 3; ++j) {
        result[3 * (first + k) + j] = u[j];
      }
    }
  }
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
      startPointBlock(block, points, first, n);
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
        omega[numCells * (first + k) + c] += nearCorrection(m, SolidAngleIntegrand{x0})[0];
      }
    }
  }
}

template <class Kernel>
void LayerPotentials<Kernel>::startPointBlock(TargetBlock& block, const double* points, int first, int n)
{
  block.start(std::min(targetBlockSize, n - first));
  for (int k = 0; k < block.size; ++k) {
    block.x[k] = points[3 * (first + k)];
    block.y[k] = points[3 * (first + k) + 1];
    block.z[k] = points[3 * (first + k) + 2];
  }
  block.pad();
}

} // namespace capsula::operators
