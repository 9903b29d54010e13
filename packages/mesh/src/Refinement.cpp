#include <capsula/mesh/Refinement.hpp>

#include <capsula/core/Error.hpp>
#include <capsula/mesh/ElementGeometry.hpp>
#include <capsula/mesh/ShapeFunctions.hpp>

#include <array>
#include <cstddef>
#include <utility>

namespace capsula::mesh {

using core::InputError;
using core::require;

namespace {

std::size_t at(int i)
{
  return static_cast<std::size_t>(i);
}

/// Local index (0..2) of the longest vertex-to-vertex edge of element e (the first of
/// equally long ones).
int longestEdge(const SurfaceMesh& mesh, int e)
{
  const ElementNodes x = mesh.elementNodes(e);
  int longest = 0;
  double length = -1.0;
  for (int k = 0; k < 3; ++k) {
    const double l = (x[at((k + 1) % 3)] - x[at(k)]).norm();
    if (l > length) {
      length = l;
      longest = k;
    }
  }
  return longest;
}

/// Builds the children of split elements and places the new nodes.
class Splitter {
public:
  Splitter(const SurfaceMesh& mesh, const std::vector<std::vector<double>>& fields)
      : mesh_(mesh),
        fields_(fields),
        positions_(mesh.positions()),
        newFields_(fields),
        halfNodes_(at(mesh.numEdges()), {-1, -1})
  {
    for (const auto& field : fields) {
      components_.push_back(static_cast<int>(field.size()) / mesh.numNodes());
    }
  }

  void keep(int e) { addChild(e, mesh_.element(e)); }

  /// Four children; local nodes 0..5 = v0, v1, v2, m01, m12, m20.
  void splitRed(int e)
  {
    beginParent(e);
    const ElementConnectivity& n = mesh_.element(e);
    const int h01v0 = halfNode(0, 0), h01v1 = halfNode(0, 1);
    const int h12v1 = halfNode(1, 1), h12v2 = halfNode(1, 2);
    const int h20v2 = halfNode(2, 2), h20v0 = halfNode(2, 0);
    const int i34 = interiorNode(3, 4), i45 = interiorNode(4, 5), i53 = interiorNode(5, 3);
    addChild(e, {n[0], n[3], n[5], h01v0, i53, h20v0});
    addChild(e, {n[3], n[1], n[4], h01v1, h12v1, i34});
    addChild(e, {n[5], n[4], n[2], i45, h12v2, h20v2});
    addChild(e, {n[3], n[4], n[5], i34, i45, i53});
  }

  /// Bisection across the longest local edge l = (a, b): children (a, m, o) and (m, b, o)
  /// with m its midside node and o the opposite vertex. For a blue split, `second` (the
  /// other refined local edge, or -1) is then bisected in the child that holds it, from m.
  void splitGreenOrBlue(int e, int l, int second)
  {
    beginParent(e);
    const ElementConnectivity& n = mesh_.element(e);
    const int a = l, b = (l + 1) % 3, o = (l + 2) % 3, m = 3 + l;
    const int edgeBO = b, edgeOA = o; // local edge k joins vertices k and k + 1
    const int midBO = 3 + edgeBO, midOA = 3 + edgeOA;
    const int bisector = interiorNode(m, o);
    if (second == edgeBO) {
      // (m, b, o) splits into (m, b, midBO) and (m, midBO, o).
      const int inner = interiorNode(m, midBO);
      addChild(e, {n[at(a)], n[at(m)], n[at(o)], halfNode(l, a), bisector, n[at(midOA)]});
      addChild(e, {n[at(m)], n[at(b)], n[at(midBO)], halfNode(l, b), halfNode(edgeBO, b), inner});
      addChild(e, {n[at(m)], n[at(midBO)], n[at(o)], inner, halfNode(edgeBO, o), bisector});
    } else if (second == edgeOA) {
      // (a, m, o) splits into (a, m, midOA) and (m, o, midOA).
      const int inner = interiorNode(m, midOA);
      addChild(e, {n[at(a)], n[at(m)], n[at(midOA)], halfNode(l, a), inner, halfNode(edgeOA, a)});
      addChild(e, {n[at(m)], n[at(o)], n[at(midOA)], bisector, halfNode(edgeOA, o), inner});
      addChild(e, {n[at(m)], n[at(b)], n[at(o)], halfNode(l, b), n[at(midBO)], bisector});
    } else {
      addChild(e, {n[at(a)], n[at(m)], n[at(o)], halfNode(l, a), bisector, n[at(midOA)]});
      addChild(e, {n[at(m)], n[at(b)], n[at(o)], halfNode(l, b), n[at(midBO)], bisector});
    }
  }

  RefinedMesh finish(std::vector<ElementSplit> splits)
  {
    return RefinedMesh{SurfaceMesh(std::move(positions_), std::move(elements_)), std::move(newFields_),
                       std::move(parents_), std::move(splits)};
  }

private:
  /// Makes element e the parent whose map places the nodes that follow.
  void beginParent(int e)
  {
    parent_ = e;
    parameters_ = shapeParameters(mesh_.elementNodes(e));
    for (int i = 0; i < 6; ++i) {
      parametric_[at(i)] = nodeParametricCoordinates(parameters_, i);
    }
  }

  /// A new node at the parametric midpoint of the parent's local nodes i and j:
  /// f = sum_k phi_k f_k over the parent's nodes, for the positions and every field.
  int addNode(int i, int j)
  {
    const double xi = 0.5 * (parametric_[at(i)][0] + parametric_[at(j)][0]);
    const double eta = 0.5 * (parametric_[at(i)][1] + parametric_[at(j)][1]);
    double phi[6];
    shapeFunctions(parameters_, xi, eta, phi);
    const ElementConnectivity& n = mesh_.element(parent_);
    const auto interpolate = [&](const double* values, int components, int d) {
      double value = 0.0;
      for (std::size_t k = 0; k < 6; ++k) {
        value += phi[k] * values[at(components) * at(n[k]) + at(d)];
      }
      return value;
    };
    for (int d = 0; d < 3; ++d) {
      positions_.push_back(interpolate(mesh_.positionData(), 3, d));
    }
    for (std::size_t f = 0; f < fields_.size(); ++f) {
      for (int d = 0; d < components_[f]; ++d) {
        newFields_[f].push_back(interpolate(fields_[f].data(), components_[f], d));
      }
    }
    return static_cast<int>(positions_.size() / 3) - 1;
  }

  /// Midside node of a child edge inside the parent (between local nodes i and j).
  int interiorNode(int i, int j) { return addNode(i, j); }

  /// Midside node of the half of the parent's local edge k that ends at local vertex
  /// `end`, created on first use and then shared with the element across the edge.
  int halfNode(int k, int end)
  {
    const int edgeIndex = mesh_.elementEdge(parent_, k);
    const int side = mesh_.edge(edgeIndex).vertices[0] == mesh_.element(parent_)[at(end)] ? 0 : 1;
    int& node = halfNodes_[at(edgeIndex)][at(side)];
    if (node < 0) {
      node = addNode(end, 3 + k);
    }
    return node;
  }

  void addChild(int parent, const ElementConnectivity& child)
  {
    elements_.push_back(child);
    parents_.push_back(parent);
  }

  const SurfaceMesh& mesh_;
  const std::vector<std::vector<double>>& fields_;
  std::vector<int> components_;
  std::vector<double> positions_;
  std::vector<std::vector<double>> newFields_;
  std::vector<std::array<int, 2>> halfNodes_; // per old edge: half at vertices[0], at vertices[1]
  std::vector<ElementConnectivity> elements_;
  std::vector<int> parents_;
  int parent_ = -1;
  ShapeParameters parameters_;
  std::array<std::array<double, 2>, 6> parametric_{};
};

/// The refined local edges of element e, and how many.
int refinedEdges(const SurfaceMesh& mesh, const std::vector<char>& edgeRefined, int e, std::array<bool, 3>& refined)
{
  int count = 0;
  for (int k = 0; k < 3; ++k) {
    refined[at(k)] = edgeRefined[at(mesh.elementEdge(e, k))] != 0;
    count += refined[at(k)] ? 1 : 0;
  }
  return count;
}

/// Which edges the closure of the marked elements refines: all edges of the marked
/// elements, then, until nothing changes, the longest edge of every element with a
/// refined edge.
std::vector<char> closeRefinement(const SurfaceMesh& mesh, const std::vector<int>& markedElements)
{
  std::vector<char> edgeRefined(at(mesh.numEdges()), 0);
  std::vector<int> toCheck; // elements across a newly refined edge
  const auto refine = [&](int e, int k) {
    char& refined = edgeRefined[at(mesh.elementEdge(e, k))];
    if (!refined) {
      refined = 1;
      toCheck.push_back(mesh.neighbour(e, k));
    }
  };
  for (int e : markedElements) {
    require<InputError>(e >= 0 && e < mesh.numElements(), "refineElements: element ", e, " is outside 0..",
                        mesh.numElements() - 1);
    for (int k = 0; k < 3; ++k) {
      refine(e, k);
    }
  }
  while (!toCheck.empty()) {
    const int e = toCheck.back();
    toCheck.pop_back();
    refine(e, longestEdge(mesh, e));
  }
  return edgeRefined;
}

ElementSplit splitOf(int refinedCount)
{
  switch (refinedCount) {
  case 0:
    return ElementSplit::Kept;
  case 1:
    return ElementSplit::Green;
  case 2:
    return ElementSplit::Blue;
  default:
    return ElementSplit::Red;
  }
}

} // namespace

std::vector<ElementSplit> refinementPlan(const SurfaceMesh& mesh, const std::vector<int>& markedElements)
{
  const std::vector<char> edgeRefined = closeRefinement(mesh, markedElements);
  std::vector<ElementSplit> splits(at(mesh.numElements()));
  std::array<bool, 3> refined{};
  for (int e = 0; e < mesh.numElements(); ++e) {
    splits[at(e)] = splitOf(refinedEdges(mesh, edgeRefined, e, refined));
  }
  return splits;
}

RefinedMesh refineElements(const SurfaceMesh& mesh, const std::vector<int>& markedElements,
                           const std::vector<std::vector<double>>& fields)
{
  const auto numNodes = at(mesh.numNodes());
  for (std::size_t f = 0; f < fields.size(); ++f) {
    require<InputError>(!fields[f].empty() && fields[f].size() % numNodes == 0, "refineElements: field ", f, " holds ",
                        fields[f].size(), " values; it must hold the same number (>= 1) for each of the ", numNodes,
                        " nodes");
  }
  const std::vector<char> edgeRefined = closeRefinement(mesh, markedElements);
  std::vector<ElementSplit> splits(at(mesh.numElements()));
  Splitter splitter(mesh, fields);
  std::array<bool, 3> refined{};
  for (int e = 0; e < mesh.numElements(); ++e) {
    const ElementSplit split = splitOf(refinedEdges(mesh, edgeRefined, e, refined));
    splits[at(e)] = split;
    if (split == ElementSplit::Kept) {
      splitter.keep(e);
    } else if (split == ElementSplit::Red) {
      splitter.splitRed(e);
    } else {
      // The closure refined the longest edge l; a blue split has one more.
      const int l = longestEdge(mesh, e);
      int second = -1;
      for (int k = 0; k < 3; ++k) {
        second = (k != l && refined[at(k)]) ? k : second;
      }
      splitter.splitGreenOrBlue(e, l, second);
    }
  }
  return splitter.finish(std::move(splits));
}

} // namespace capsula::mesh
