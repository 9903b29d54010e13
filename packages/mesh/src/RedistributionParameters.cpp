#include "capsula/mesh/RedistributionParameters.hpp"

#include <capsula/core/ParameterDeclaration.hpp>

namespace capsula::mesh {

namespace core = capsula::core;

void declareRedistributionParameters(Teuchos::ParameterList& list)
{
  core::declareBool(list, "Enabled", false,
                    "Move the nodes of a cell along its surface to better-shaped elements when the "
                    "flow has degraded them, carrying each node's reference (unstressed) position "
                    "with it, so the elastic state is kept (docs/stability.md). Off: the mesh "
                    "follows the material points only.");
  core::declareReal(list, "Minimum angle", 25.0,
                    "Redistribute a cell's nodes after any time step that leaves one of its elements "
                    "with a corner angle below this many degrees (the level-1..3 icospheres start at "
                    "54-56). Keep it above 'Output/Stability/Minimum angle', the bound that stops a "
                    "run.",
                    core::greaterThan(0.0), core::lessThan(60.0));
  core::declareInt(list, "Passes", 10,
                   "Smoothing passes per redistribution at most; they stop as soon as the smallest "
                   "angle stops improving.",
                   1, 100);
  core::declareReal(list, "Relaxation", 0.5,
                    "Fraction of the way to the mean of its vertex neighbours that a vertex moves "
                    "per pass (tangentially).",
                    core::greaterThan(0.0), core::atMost(1.0));
  core::declareBool(list, "Preserve volume", true,
                    "Offset the redistributed surface along its normals so that it encloses the "
                    "volume it had before: re-interpolating the quadratic elements shrinks a "
                    "curved surface slightly (about h^4).");
}

RedistributionSettings readRedistributionParameters(const Teuchos::ParameterList& list)
{
  RedistributionSettings settings;
  settings.enabled = list.get<bool>("Enabled");
  settings.triggerAngle = list.get<double>("Minimum angle");
  settings.options.passes = list.get<int>("Passes");
  settings.options.relaxation = list.get<double>("Relaxation");
  settings.options.preserveVolume = list.get<bool>("Preserve volume");
  return settings;
}

} // namespace capsula::mesh
