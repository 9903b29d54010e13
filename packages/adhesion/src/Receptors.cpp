#include "capsula/adhesion/Receptors.hpp"

#include "capsula/adhesion/CounterRandom.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/mesh/ElementGeometry.hpp>
#include <capsula/mesh/Measures.hpp>
#include <capsula/quadrature/TriangleRule.hpp>

#include <cmath>
#include <map>

namespace capsula::adhesion {

namespace core = capsula::core;

namespace {

std::vector<mesh::ShapeParameters> referenceShapeParameters(const mesh::SurfaceMesh& mesh,
                                                            const std::vector<double>& reference)
{
  core::require<core::InputError>(reference.size() == 3 * static_cast<std::size_t>(mesh.numNodes()),
                                  "Receptors: the reference shape has ", reference.size() / 3, " nodes, the mesh ",
                                  mesh.numNodes(), ".");
  std::vector<mesh::ShapeParameters> parameters(static_cast<std::size_t>(mesh.numElements()));
  for (int e = 0; e < mesh.numElements(); ++e) {
    parameters[static_cast<std::size_t>(e)] = mesh::shapeParameters(mesh.elementNodes(e, reference.data()));
  }
  return parameters;
}

// The R2 sequence's increments: 1/g and 1/g^2, g the plastic number (g^3 = g + 1).
constexpr double plastic = 1.32471795724474602596;
constexpr double r2StepX = 1.0 / plastic;
constexpr double r2StepY = 1.0 / (plastic * plastic);

} // namespace

ReceptorSet::ReceptorSet(const mesh::SurfaceMesh& mesh, const std::vector<double>& referencePositions, double density,
                         std::uint64_t seed, std::uint64_t stream)
    : parameters_(referenceShapeParameters(mesh, referencePositions))
{
  core::require<core::InputError>(density >= 0.0, "Receptors: the density ", density, " is negative.");
  const std::vector<double> areas = mesh::elementAreas(mesh, referencePositions.data());
  for (int e = 0; e < mesh.numElements(); ++e) {
    const double expected = density * areas[static_cast<std::size_t>(e)];
    const auto key = static_cast<std::uint64_t>(e);
    const double whole = std::floor(expected);
    const double u = counterUniform(seed, stream, key, static_cast<std::uint64_t>(DrawPurpose::PlacementCount));
    const int count = static_cast<int>(whole) + (u < expected - whole ? 1 : 0);
    const std::uint64_t h = counterHash(seed, stream, key, static_cast<std::uint64_t>(DrawPurpose::PlacementPoint));
    const double x0 = static_cast<double>(h >> 11) * 0x1.0p-53;
    const double y0 = static_cast<double>(splitMix64(h) >> 11) * 0x1.0p-53;
    for (int k = 0; k < count; ++k) {
      double x = x0 + (k + 0.5) * r2StepX, y = y0 + (k + 0.5) * r2StepY;
      x -= std::floor(x);
      y -= std::floor(y);
      if (x + y > 1.0) { // fold the unit square onto the triangle xi + eta <= 1 (area-preserving)
        x = 1.0 - x;
        y = 1.0 - y;
      }
      receptors_.push_back({e, x, y});
    }
  }
}

ReceptorSet::ReceptorSet(const mesh::SurfaceMesh& mesh, const std::vector<double>& referencePositions,
                         std::vector<Receptor> receptors)
    : parameters_(referenceShapeParameters(mesh, referencePositions)), receptors_(std::move(receptors))
{
  for (const Receptor& r : receptors_) {
    core::require<core::InputError>(
        r.element >= 0 && r.element < mesh.numElements() && r.xi >= 0.0 && r.eta >= 0.0 && r.xi + r.eta <= 1.0,
        "Receptors: (element ", r.element, ", xi ", r.xi, ", eta ", r.eta, ") is not a point of the mesh.");
  }
}

void ReceptorSet::shapeFunctions(int r, double phi[6]) const
{
  const Receptor& receptor = (*this)[r];
  mesh::shapeFunctions(shapeParameters(receptor.element), receptor.xi, receptor.eta, phi);
}

mesh::Vec3 ReceptorSet::position(const mesh::SurfaceMesh& mesh, const double* positions, int r) const
{
  if (patched()) {
    mesh::Vec3 x = mesh::Vec3::Zero();
    for (const NodeWeight& c : patches_[static_cast<std::size_t>(r)]) {
      x += c.weight * mesh::nodeAt(positions, c.node);
    }
    return x;
  }
  const Receptor& receptor = (*this)[r];
  return mesh::surfacePosition(mesh.elementNodes(receptor.element, positions), shapeParameters(receptor.element),
                               receptor.xi, receptor.eta);
}

void ReceptorSet::nodeWeights(const mesh::SurfaceMesh& mesh, int r, std::vector<NodeWeight>& out) const
{
  if (patched()) {
    out = patches_[static_cast<std::size_t>(r)];
    return;
  }
  double phi[6];
  shapeFunctions(r, phi);
  const auto& nodes = mesh.element((*this)[r].element);
  out.resize(6);
  for (std::size_t k = 0; k < 6; ++k) {
    out[k] = {nodes[k], phi[k]};
  }
}

void ReceptorSet::spreadOverPatches(const mesh::SurfaceMesh& mesh, const std::vector<double>& referencePositions,
                                    double radius, const std::string& key)
{
  core::require<core::InputError>(radius > 0.0, "'", key, "' = ", radius, ": a patch needs a radius > 0.");
  // Every quadrature point of the unstressed shape once: its element, phi and area weight.
  struct Point {
    int element;
    mesh::Vec3 x;
    double phi[6];
    double area;
  };
  const quadrature::TriangleRule& rule = quadrature::triangleRule(7);
  std::vector<Point> points;
  points.reserve(static_cast<std::size_t>(mesh.numElements() * rule.size()));
  for (int e = 0; e < mesh.numElements(); ++e) {
    const mesh::ElementNodes x = mesh.elementNodes(e, referencePositions.data());
    for (int q = 0; q < rule.size(); ++q) {
      const auto k = static_cast<std::size_t>(q);
      const mesh::SurfacePoint s = mesh::evaluateSurfacePoint(x, shapeParameters(e), rule.xi[k], rule.eta[k]);
      Point p{e, s.position, {}, rule.weight[k] * s.metric};
      mesh::shapeFunctions(shapeParameters(e), rule.xi[k], rule.eta[k], p.phi);
      points.push_back(p);
    }
  }
  std::vector<std::vector<NodeWeight>> patches(receptors_.size());
  for (int r = 0; r < size(); ++r) {
    const mesh::Vec3 centre = position(mesh, referencePositions.data(), r);
    std::map<int, double> shares; // by node, so every rank sums in the same order
    double total = 0.0;
    int count = 0;
    for (const Point& p : points) {
      const double r2 = (p.x - centre).squaredNorm() / (radius * radius);
      if (r2 >= 1.0) {
        continue;
      }
      const double w = p.area * (1.0 - r2) * (1.0 - r2);
      const auto& nodes = mesh.element(p.element);
      for (std::size_t k = 0; k < 6; ++k) {
        shares[nodes[k]] += w * p.phi[k];
      }
      total += w;
      ++count;
    }
    core::require<core::InputError>(count >= 3, "'", key, "' = ", radius, ": the patch of receptor ", r, " holds ",
                                    count,
                                    " quadrature point(s) of this mesh; give a radius that holds at least three "
                                    "(about the element size) or 0 for point receptors.");
    for (const auto& [node, share] : shares) {
      patches[static_cast<std::size_t>(r)].push_back({node, share / total});
    }
  }
  patches_ = std::move(patches);
}

} // namespace capsula::adhesion
