#include "capsula/scene/SceneBounds.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/elasticity/BendingLoadBound.hpp>
#include <capsula/mesh/EquivalentEllipsoid.hpp>

#include <algorithm>

namespace capsula::scene {

namespace core = capsula::core;

namespace {

// The cell with the smallest semi-axis, and that semi-axis.
std::pair<std::size_t, double> smallestCell(const std::vector<double>& semiAxes)
{
  const auto it = std::min_element(semiAxes.begin(), semiAxes.end());
  return {static_cast<std::size_t>(it - semiAxes.begin()), *it};
}

} // namespace

std::vector<double> smallestSemiAxes(const std::vector<mesh::SurfaceMesh>& cells)
{
  std::vector<double> semiAxes;
  semiAxes.reserve(cells.size());
  for (const auto& cell : cells) {
    semiAxes.push_back(mesh::equivalentEllipsoid(cell).semiAxes[2]); // l1 >= l2 >= l3
  }
  return semiAxes;
}

void requireContactRangeWithinCells(const SceneDescription& description, const std::vector<double>& semiAxes)
{
  if (!description.contact.enabled || semiAxes.empty()) {
    return;
  }
  const auto [c, smallest] = smallestCell(semiAxes);
  core::require<core::InputError>(description.contact.range < smallest, "'Contact/Range' = ", description.contact.range,
                                  " is not below the smallest semi-axis of '", description.cells[c].path, "', ",
                                  smallest,
                                  " a: the repulsion would reach across the cell and push on the membrane facing "
                                  "away from the wall as well, and fold it. Give a range below ",
                                  smallest, " (a short-range repulsion: 0.03-0.05 a).");
}

void requireRepresentableBending(const SceneDescription& description, const std::vector<double>& semiAxes)
{
  for (std::size_t c = 0; c < description.cells.size() && c < semiAxes.size(); ++c) {
    const CellDescription& cell = description.cells[c];
    elasticity::BendingBoundInput input;
    input.modulus = cell.bendingModulus;
    input.spontaneousCurvature = cell.spontaneousCurvature;
    input.shapeCurvature = 1.0 / semiAxes[c];
    input.capillaryNumber = description.capillaryNumber;
    input.modulusKey = cell.path + "/Bending modulus";
    input.curvatureKey = cell.path + "/Spontaneous curvature";
    input.capillaryKey = "Flow/Capillary number";
    elasticity::requireRepresentableBending(input);
  }
}

void requireSceneWithinBounds(const SceneDescription& description, const std::vector<mesh::SurfaceMesh>& cells)
{
  const std::vector<double> semiAxes = smallestSemiAxes(cells);
  requireContactRangeWithinCells(description, semiAxes);
  requireRepresentableBending(description, semiAxes);
}

void requireToleranceBelowCellSize(double tolerance, const std::string& key, const SceneDescription& description,
                                   const std::vector<double>& semiAxes)
{
  if (semiAxes.empty()) {
    return;
  }
  const auto [c, smallest] = smallestCell(semiAxes);
  const double largest = kToleranceFraction * smallest;
  core::require<core::InputError>(tolerance <= largest, "'", key, "' = ", tolerance,
                                  " lets a step err in the node positions by as much as ", tolerance / smallest * 100.0,
                                  "% of the smallest semi-axis of '", description.cells[c].path, "' (", smallest,
                                  " a): the error control would accept steps whose error is the deformation itself. "
                                  "Give a tolerance <= ",
                                  largest, " (1% of it; the studies use 1e-6 to 1e-4).");
}

} // namespace capsula::scene
