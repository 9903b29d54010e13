#pragma once
// Part of LayerPotentials.hpp, included at its end: the set-up for a mesh and its geometry,
// and the search for the elements near a target. The class and what it computes are
// described there.

namespace capsula::operators {

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

template <class Kernel, class = void>
struct HasOwnFarField : std::false_type {};
template <class Kernel>
struct HasOwnFarField<Kernel, std::void_t<decltype(std::declval<const Kernel&>().farFieldSummation())>>
    : std::true_type {};

// The centre of element m's bounding sphere.
inline void elementCentre(const ElementData& elements, int m, double centre[3])
{
  centre[0] = elements.cx[m];
  centre[1] = elements.cy[m];
  centre[2] = elements.cz[m];
}

} // namespace detail

template <class Kernel>
LayerPotentials<Kernel>::LayerPotentials(const DiscretisationParameters& parameters, Kernel kernel)
    : kernel_(std::move(kernel)),
      traits_(kernelTraits(kernel_)),
      parameters_(parameters),
      quadrature_(parameters.quadraturePoints),
      gauss_(quadrature::gaussLegendre(parameters.singularQuadraturePoints, 0.0, 1.0))
{
  if constexpr (detail::HasOwnFarField<Kernel>::value) {
    if (!parameters.farField) {
      farField_ = kernel_.farFieldSummation();
    }
  }
  if (!farField_ && parameters.farField) {
    farField_ = parameters.farField->forKernel(typeid(Kernel), Kernel::name);
    core::require<core::InputError>(farField_ != nullptr, "'Operator/Summation' = ", parameters.farField->name(),
                                    " does not support the ", Kernel::name,
                                    " kernel ('Operator/Kernel'); use 'Operator/Summation' = Direct or another "
                                    "kernel.");
  } else if (!farField_) {
    farField_ = std::make_unique<DirectSummation<Kernel>>(kernel_);
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
    core::require<core::InputError>(traits_.inFluid(positions + 3 * g), "Node ", g,
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
  if (reach <= 0.0 || traits_.vanishesAt(x0)) {
    return;
  }
  double poles[KernelTraits<Kernel>::maxImages + 1][3];
  for (int i = 0; i < 3; ++i) {
    poles[0][i] = x0[i];
  }
  int numPoles = 1 + traits_.images(x0, poles + 1);
  for (std::size_t c = 0; c < cells_.size(); ++c) {
    const CellReach& cell = cellReach_[c];
    // A periodic kernel: the pole's image next to this cell, and that image's images.
    double shifted[3];
    traits_.nearestImage(x0, cell.centre, shifted);
    if (shifted[0] != poles[0][0] || shifted[1] != poles[0][1] || shifted[2] != poles[0][2]) {
      for (int i = 0; i < 3; ++i) {
        poles[0][i] = shifted[i];
      }
      numPoles = 1 + traits_.images(shifted, poles + 1);
    }
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

} // namespace capsula::operators
