#include "capsula/adhesion/Receptors.hpp"

#include "capsula/adhesion/CounterRandom.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/mesh/ElementGeometry.hpp>
#include <capsula/mesh/Measures.hpp>

#include <cmath>

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
  const Receptor& receptor = (*this)[r];
  return mesh::surfacePosition(mesh.elementNodes(receptor.element, positions), shapeParameters(receptor.element),
                               receptor.xi, receptor.eta);
}

} // namespace capsula::adhesion
