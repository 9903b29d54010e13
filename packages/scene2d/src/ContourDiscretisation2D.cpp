#include "capsula/scene2d/ContourDiscretisation2D.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>
#include <capsula/quadrature/LogWeightedGauss.hpp>

#include <cmath>

namespace capsula::scene2d {

void declareContourDiscretisation2D(Teuchos::ParameterList& discretisation)
{
  namespace core = capsula::core;
  const ContourDiscretisation2D defaults;
  core::declareInt(discretisation, "Gauss-Legendre points", defaults.gaussLegendrePoints,
                   "N_GL, Gauss-Legendre points per contour segment (thesis eq A.40). 6 is the "
                   "thesis choice (Table 3.2); the cost of a velocity evaluation is proportional to it.",
                   1, 64);
  core::declareInt(discretisation, "Log-weighted points", defaults.logWeightedPoints,
                   "Points of the Gauss rule with weight -ln(t) for the logarithmic singularity "
                   "of the single layer on the two segments that hold the target node (thesis "
                   "eqs A.46-A.47).",
                   1, quadrature::maxLogWeightedGaussOrder);
  core::declareReal(discretisation, "Near-singular distance", defaults.nearSingularDistance,
                    "A piece of a segment closer than this many of its own lengths to the target "
                    "node or to its image below the wall is bisected, up to 'Near-singular "
                    "levels' times. 0 turns the subdivision off (thesis practice, inaccurate next to "
                    "the wall); docs/tether2d.md gives the errors of both.",
                    core::atLeast(0.0));
  core::declareInt(discretisation, "Near-singular levels", defaults.nearSingularLevels,
                   "Most bisections of one segment by the near-singular subdivision.", 0, 20);
}

ContourDiscretisation2D readContourDiscretisation2D(const Teuchos::ParameterList& discretisation)
{
  ContourDiscretisation2D p;
  p.gaussLegendrePoints = discretisation.get<int>("Gauss-Legendre points");
  p.logWeightedPoints = discretisation.get<int>("Log-weighted points");
  p.nearSingularDistance = discretisation.get<double>("Near-singular distance");
  p.nearSingularLevels = discretisation.get<int>("Near-singular levels");
  validate(p);
  return p;
}

void validate(const ContourDiscretisation2D& p)
{
  using core::InputError;
  using core::require;
  require<InputError>(p.gaussLegendrePoints >= 1 && p.gaussLegendrePoints <= 64,
                      "Discretisation/Gauss-Legendre points must be from 1 to 64, got ", p.gaussLegendrePoints, ".");
  require<InputError>(p.logWeightedPoints >= 1 && p.logWeightedPoints <= quadrature::maxLogWeightedGaussOrder,
                      "Discretisation/Log-weighted points must be from 1 to ", quadrature::maxLogWeightedGaussOrder,
                      ", got ", p.logWeightedPoints, ".");
  require<InputError>(std::isfinite(p.nearSingularDistance) && p.nearSingularDistance >= 0.0,
                      "Discretisation/Near-singular distance must be >= 0, got ", p.nearSingularDistance, ".");
  require<InputError>(p.nearSingularLevels >= 0 && p.nearSingularLevels <= 20,
                      "Discretisation/Near-singular levels must be from 0 to 20, got ", p.nearSingularLevels, ".");
}

} // namespace capsula::scene2d
