#include "capsula/mesh/NodeRedistribution.hpp"

#include "capsula/mesh/Measures.hpp"
#include "capsula/mesh/MeshQuality.hpp"
#include "capsula/mesh/NodeNormals.hpp"

#include <capsula/core/Error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace capsula::mesh {

namespace core = capsula::core;

ElementClosestPoint closestPointOnElement(const ElementNodes& nodes, const ShapeParameters& parameters,
                                          const Vec3& target)
{
  double xi = 1.0 / 3.0, eta = 1.0 / 3.0;
  // Gauss-Newton on |x(xi, eta) - target|^2, each step projected back into the triangle.
  // Near the surface the residual is small against the curvature radius, so it converges
  // in a few steps; 30 only guards against a target far off the element.
  for (int iteration = 0; iteration < 30; ++iteration) {
    const SurfacePoint s = evaluateSurfacePoint(nodes, parameters, xi, eta);
    const Vec3 r = s.position - target;
    const double a = s.tangentXi.dot(s.tangentXi), b = s.tangentXi.dot(s.tangentEta),
                 c = s.tangentEta.dot(s.tangentEta);
    const double gXi = s.tangentXi.dot(r), gEta = s.tangentEta.dot(r);
    const double det = a * c - b * b;
    double nextXi = xi - (c * gXi - b * gEta) / det;
    double nextEta = eta - (a * gEta - b * gXi) / det;
    if (nextXi + nextEta > 1.0) { // onto the hypotenuse, then into its ends
      const double excess = 0.5 * (nextXi + nextEta - 1.0);
      nextXi -= excess;
      nextEta -= excess;
    }
    nextXi = std::clamp(nextXi, 0.0, 1.0);
    nextEta = std::clamp(nextEta, 0.0, 1.0 - nextXi);
    const double change = std::abs(nextXi - xi) + std::abs(nextEta - eta);
    xi = nextXi;
    eta = nextEta;
    if (change < 1e-14) {
      break;
    }
  }
  return {xi, eta, (surfacePosition(nodes, parameters, xi, eta) - target).squaredNorm()};
}

namespace {

// Where a node sits on the surface the redistribution started from.
struct Located {
  int element = -1;
  double xi = 0.0, eta = 0.0;
};

// The surface before the redistribution: every pass projects onto it (never onto the
// previous pass's result, whose re-interpolation would cut the corners of a curved surface
// again at every pass and round the cell off).
struct OriginalSurface {
  const SurfaceMesh& mesh;
  const std::vector<double>& positions;
  const std::vector<double>& reference;
  std::vector<ShapeParameters> parameters;  // from the reference: material (xi, eta)
  std::vector<ElementNodes> nodes;          // current positions per element
  std::vector<ElementNodes> referenceNodes; // reference positions per element
  std::vector<std::vector<int>> nearby;     // elements sharing a vertex with each element

  OriginalSurface(const SurfaceMesh& m, const std::vector<double>& x, const std::vector<double>& X)
      : mesh(m), positions(x), reference(X)
  {
    const auto numElements = static_cast<std::size_t>(mesh.numElements());
    parameters.resize(numElements);
    nodes.resize(numElements);
    referenceNodes.resize(numElements);
    nearby.resize(numElements);
    for (int e = 0; e < mesh.numElements(); ++e) {
      const auto k = static_cast<std::size_t>(e);
      parameters[k] = shapeParameters(mesh.elementNodes(e, reference.data()));
      nodes[k] = mesh.elementNodes(e, positions.data());
      referenceNodes[k] = mesh.elementNodes(e, reference.data());
      for (int i = 0; i < 3; ++i) {
        for (const auto& incidence : mesh.incidentElements(mesh.element(e)[static_cast<std::size_t>(i)])) {
          nearby[k].push_back(incidence.element);
        }
      }
      std::sort(nearby[k].begin(), nearby[k].end());
      nearby[k].erase(std::unique(nearby[k].begin(), nearby[k].end()), nearby[k].end());
    }
  }

  // The closest point to `target` over the elements near those in `around`, measured in
  // the current configuration or (inReference) in the reference one.
  Located locate(std::initializer_list<int> around, const Vec3& target, std::vector<int>& candidates,
                 bool inReference = false) const
  {
    candidates.clear();
    for (const int e : around) {
      const auto& near = nearby[static_cast<std::size_t>(e)];
      candidates.insert(candidates.end(), near.begin(), near.end());
    }
    Located best;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (const int e : candidates) {
      const auto k = static_cast<std::size_t>(e);
      const auto point = closestPointOnElement(inReference ? referenceNodes[k] : nodes[k], parameters[k], target);
      if (point.squaredDistance < bestDistance) {
        bestDistance = point.squaredDistance;
        best = {e, point.xi, point.eta};
      }
    }
    return best;
  }

  // x and X of the material point `where`, into node `node` of the output arrays.
  void place(const Located& where, int node, std::vector<double>& x, std::vector<double>& X) const
  {
    double phi[6];
    shapeFunctions(parameters[static_cast<std::size_t>(where.element)], where.xi, where.eta, phi);
    const auto& connectivity = mesh.element(where.element);
    for (std::size_t d = 0; d < 3; ++d) {
      double px = 0.0, pX = 0.0;
      for (std::size_t i = 0; i < 6; ++i) {
        px += phi[i] * positions[3 * static_cast<std::size_t>(connectivity[i]) + d];
        pX += phi[i] * reference[3 * static_cast<std::size_t>(connectivity[i]) + d];
      }
      x[3 * static_cast<std::size_t>(node) + d] = px;
      X[3 * static_cast<std::size_t>(node) + d] = pX;
    }
  }
};

double smallestAngle(SurfaceMesh& scratch, const std::vector<double>& positions)
{
  scratch.setPositions(positions);
  return meshQuality(scratch).minAngle;
}

// One smoothing pass (steps 1-3 of the header): new x and X from the nodes' present
// positions `x`, projected onto the original surface; `located` (per node) is where each
// node sat after the previous pass and is updated.
void smoothOnce(const OriginalSurface& original, double relaxation, const std::vector<char>& movable,
                std::vector<double>& x, std::vector<double>& X, std::vector<Located>& located)
{
  const SurfaceMesh& mesh = original.mesh;
  const std::vector<Vec3> normals = nodeNormals(mesh, x.data());
  std::vector<double> newX = x, newReference = X;
  std::vector<Located> newLocated = located;
  std::vector<int> candidates, ring;
  for (int v = 0; v < mesh.numNodes(); ++v) {
    if (!mesh.isVertex(v) || !movable[static_cast<std::size_t>(v)]) {
      continue;
    }
    ring.clear();
    for (const auto& incidence : mesh.incidentElements(v)) {
      for (std::size_t i = 0; i < 3; ++i) {
        const int w = mesh.element(incidence.element)[i];
        if (w != v) {
          ring.push_back(w);
        }
      }
    }
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    const Vec3 position = nodeAt(x.data(), v);
    Vec3 mean = Vec3::Zero();
    for (const int w : ring) {
      mean += nodeAt(x.data(), w);
    }
    mean /= static_cast<double>(ring.size());
    const Vec3& n = normals[static_cast<std::size_t>(v)];
    Vec3 move = relaxation * (mean - position);
    move -= move.dot(n) * n;
    const auto k = static_cast<std::size_t>(v);
    newLocated[k] = original.locate({located[k].element}, position + move, candidates);
    original.place(newLocated[k], v, newX, newReference);
  }
  // Midside nodes at the middle of their edges in the REFERENCE configuration: the
  // membrane parametrises both configurations by the reference (alpha, beta, gamma), and a
  // midside node far from its reference edge's middle bends that map until its Jacobian
  // vanishes at an end node (alpha < 0.29 or > 0.71 for a straight edge stretched
  // uniformly). The Lagrangian mesh starts that way and keeps it; so does this.
  for (const Edge& edge : mesh.edges()) {
    const auto a = static_cast<std::size_t>(edge.vertices[0]), b = static_cast<std::size_t>(edge.vertices[1]);
    if (!movable[a] && !movable[b]) { // both ends stay: so does the edge
      continue;
    }
    const Vec3 middle =
        0.5 * (nodeAt(newReference.data(), edge.vertices[0]) + nodeAt(newReference.data(), edge.vertices[1]));
    const auto m = static_cast<std::size_t>(edge.midNode);
    newLocated[m] =
        original.locate({newLocated[a].element, newLocated[b].element}, middle, candidates, /*inReference=*/true);
    original.place(newLocated[m], edge.midNode, newX, newReference);
  }
  x.swap(newX);
  X.swap(newReference);
  located.swap(newLocated);
}

// Offsets every node along its normal by the one distance that gives the surface the
// volume `target`; returns the distance. Newton on V(delta) with dV/d(delta) ~ A: the slope
// is that of a smooth surface, so each step gains a factor of ~h^2 (two steps left 3e-9 of
// the volume at level 1); a few steps reach round-off.
double restoreVolume(SurfaceMesh& scratch, std::vector<double>& positions, double target)
{
  double total = 0.0;
  for (int newton = 0; newton < 6; ++newton) {
    scratch.setPositions(positions);
    const double volume = enclosedVolume(scratch);
    if (std::abs(volume - target) <= 1e-13 * std::abs(target)) {
      break;
    }
    const double delta = (target - volume) / surfaceArea(scratch);
    const std::vector<Vec3> normals = nodeNormals(scratch);
    for (std::size_t i = 0; i < normals.size(); ++i) {
      for (std::size_t d = 0; d < 3; ++d) {
        positions[3 * i + d] += delta * normals[i][static_cast<Eigen::Index>(d)];
      }
    }
    total += delta;
  }
  return total;
}

} // namespace

RedistributedNodes redistributeNodes(const SurfaceMesh& mesh, const std::vector<double>& positions,
                                     const std::vector<double>& reference, const RedistributionOptions& options)
{
  const std::size_t size = 3 * static_cast<std::size_t>(mesh.numNodes());
  core::require<core::InputError>(positions.size() == size && reference.size() == size,
                                  "redistributeNodes: ", positions.size(), " positions and ", reference.size(),
                                  " reference values for a mesh of ", mesh.numNodes(), " nodes (3 each)");
  core::require<core::InputError>(options.passes >= 1, "redistributeNodes: passes = ", options.passes,
                                  " must be at least 1");
  core::require<core::InputError>(options.improveBelow > 0.0,
                                  "redistributeNodes: improveBelow = ", options.improveBelow,
                                  " degrees must be positive");
  core::require<core::InputError>(options.relaxation > 0.0 && options.relaxation <= 1.0,
                                  "redistributeNodes: relaxation = ", options.relaxation, " must be in (0, 1]");
  SurfaceMesh scratch = mesh;
  RedistributedNodes result;
  result.positions = positions;
  result.reference = reference;
  result.minAngleBefore = smallestAngle(scratch, positions);
  result.minAngleAfter = result.minAngleBefore;
  const OriginalSurface original(mesh, positions, reference);
  // Every node starts at its own place in an element that holds it.
  std::vector<Located> located(static_cast<std::size_t>(mesh.numNodes()));
  for (int node = 0; node < mesh.numNodes(); ++node) {
    const NodeIncidence first = mesh.incidentElements(node)[0];
    const auto at =
        nodeParametricCoordinates(original.parameters[static_cast<std::size_t>(first.element)], first.localNode);
    located[static_cast<std::size_t>(node)] = {first.element, at[0], at[1]};
  }
  // The vertices that may move: those of the elements below options.improveBelow and their
  // neighbours (one ring, room to make the bad elements better). The rest of the surface
  // is not re-interpolated at all.
  std::vector<char> movable(static_cast<std::size_t>(mesh.numNodes()), 0);
  scratch.setPositions(positions);
  for (int e = 0; e < mesh.numElements(); ++e) {
    if (elementQuality(scratch, e).minAngle >= options.improveBelow) {
      continue;
    }
    for (std::size_t i = 0; i < 3; ++i) {
      for (const auto& incidence : mesh.incidentElements(mesh.element(e)[i])) {
        for (std::size_t j = 0; j < 3; ++j) {
          movable[static_cast<std::size_t>(mesh.element(incidence.element)[j])] = 1;
        }
      }
    }
  }
  const double referenceAngleBefore = smallestAngle(scratch, reference);
  const double referenceBound = std::min(options.minimumReferenceAngle, referenceAngleBefore);
  for (int pass = 0; pass < options.passes; ++pass) {
    std::vector<double> x = result.positions, X = result.reference;
    std::vector<Located> where = located;
    smoothOnce(original, options.relaxation, movable, x, X, where);
    const double angle = smallestAngle(scratch, x);
    // Keep a pass only if it improves the current mesh without squeezing the reference
    // elements too far (a material element would fold in the reference shape).
    if (!(angle > result.minAngleAfter) || !(smallestAngle(scratch, X) >= referenceBound)) {
      break;
    }
    result.positions.swap(x);
    result.reference.swap(X);
    located.swap(where);
    result.minAngleAfter = angle;
    result.passes = pass + 1;
  }
  if (options.preserveVolume && result.passes > 0) {
    scratch.setPositions(positions);
    result.volumeOffset = restoreVolume(scratch, result.positions, enclosedVolume(scratch));
    result.minAngleAfter = smallestAngle(scratch, result.positions);
  }
  result.referenceMinAngle = smallestAngle(scratch, result.reference);
  for (std::size_t i = 0; i < size; i += 3) {
    const Vec3 d(result.positions[i] - positions[i], result.positions[i + 1] - positions[i + 1],
                 result.positions[i + 2] - positions[i + 2]);
    result.maxDisplacement = std::max(result.maxDisplacement, d.norm());
  }
  return result;
}

} // namespace capsula::mesh
