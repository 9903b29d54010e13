#include "capsula/mesh/AdaptionParameters.hpp"

#include <capsula/core/ParameterDeclaration.hpp>

namespace capsula::mesh {

namespace core = capsula::core;

void declareAdaptionParameters(Teuchos::ParameterList& list)
{
  core::declareBool(list, "Enabled", false,
                    "Refine a running cell's mesh where its shape curves most (thesis eq 4.3: "
                    "elements with Q = kappa_max^2 A >= Threshold, red-green-blue closure), each new "
                    "node a material point with its reference position, so the elastic state is "
                    "kept (docs/stability.md).");
  core::declareReal(list, "Threshold", 0.2,
                    "Q_e = kappa_max^2 A_e above which an element is refined (the thesis used 0.2; a "
                    "unit sphere's level-2 elements have Q ~ 0.04, level-1 ~ 0.16).",
                    core::greaterThan(0.0));
  core::declareChoice(list, "Curvature", "quadratic fit", {"quadratic fit", "jet fit", "element average"},
                      "How the nodal curvature of Q is computed (docs/curvature.md).");
  core::declareInt(list, "Check interval", 20, "Accepted time steps between two checks of Q.", 1);
  core::declareInt(list, "Maximum elements", 5120,
                   "No refinement that would give a cell more elements than this (level 4: 5120).", 20);
}

AdaptionSettings readAdaptionParameters(const Teuchos::ParameterList& list)
{
  AdaptionSettings settings;
  settings.enabled = list.get<bool>("Enabled");
  settings.options.threshold = list.get<double>("Threshold");
  settings.options.curvature = curvatureMethodFromName(list.get<std::string>("Curvature"));
  settings.checkInterval = list.get<int>("Check interval");
  settings.maxElements = list.get<int>("Maximum elements");
  return settings;
}

} // namespace capsula::mesh
