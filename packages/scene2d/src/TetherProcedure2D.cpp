#include "capsula/scene2d/TetherProcedure2D.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>

#include <cmath>

namespace capsula::scene2d {

void declareTetherParameters2D(Teuchos::ParameterList& tether)
{
  namespace core = capsula::core;
  const TetherSettings2D defaults;
  core::declareBool(tether, "Enabled", defaults.enabled,
                    "true: the thesis's procedure (Section 4.1): a free preparation stage, then the "
                    "lowest node is fixed at (0, Anchor height). false: the cell stays free all run.");
  core::declareReal(tether, "Anchor height", defaults.anchorHeight,
                    "y of the tether point; the thesis fixed it at (0, 0.005).", core::greaterThan(0.0));
  core::declareReal(tether, "Preparation tolerance", defaults.preparationTolerance,
                    "The preparation stage ends when |d D12 / d tau| (tau = k t / lambda) falls below "
                    "this: the free cell has reached its deformed shape.",
                    core::greaterThan(0.0));
  core::declareReal(tether, "Minimum preparation time", defaults.minimumPreparationTime,
                    "tau before which the preparation stage never ends.", core::atLeast(0.0));
  core::declareReal(tether, "Maximum preparation time", defaults.maximumPreparationTime,
                    "tau at which the preparation stage ends whatever the deformation rate.",
                    core::atLeast(0.0));
}

TetherSettings2D readTetherSettings2D(const Teuchos::ParameterList& tether)
{
  TetherSettings2D s;
  s.enabled = tether.get<bool>("Enabled");
  s.anchorHeight = tether.get<double>("Anchor height");
  s.preparationTolerance = tether.get<double>("Preparation tolerance");
  s.minimumPreparationTime = tether.get<double>("Minimum preparation time");
  s.maximumPreparationTime = tether.get<double>("Maximum preparation time");
  core::require<core::InputError>(s.minimumPreparationTime <= s.maximumPreparationTime,
                                  "Tether/Minimum preparation time (", s.minimumPreparationTime,
                                  ") exceeds Tether/Maximum preparation time (", s.maximumPreparationTime,
                                  "): lower the first or raise the second.");
  return s;
}

bool preparationComplete(const TetherSettings2D& settings, double tau, double deformationRate)
{
  if (tau >= settings.maximumPreparationTime) {
    return true;
  }
  return tau >= settings.minimumPreparationTime && std::abs(deformationRate) < settings.preparationTolerance;
}

TetherPlacement2D tetherPlacement(const Eigen::Matrix2Xd& nodes, const Eigen::Vector2d& anchor)
{
  TetherPlacement2D placement;
  for (Eigen::Index i = 1; i < nodes.cols(); ++i) {
    if (nodes(1, i) < nodes(1, placement.lowestNode)) {
      placement.lowestNode = static_cast<int>(i);
    }
  }
  placement.shift = anchor - nodes.col(placement.lowestNode);
  return placement;
}

Eigen::Matrix2Xd relabelNodes(const Eigen::Matrix2Xd& nodes, int offset)
{
  const Eigen::Index n = nodes.cols();
  Eigen::Matrix2Xd result(2, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    result.col(i) = nodes.col(((i + offset) % n + n) % n);
  }
  return result;
}

Eigen::Matrix2Xd tetheredNodes(const Eigen::Matrix2Xd& nodes, const TetherPlacement2D& placement)
{
  Eigen::Matrix2Xd shifted = nodes.colwise() + placement.shift;
  return relabelNodes(shifted, placement.lowestNode);
}

} // namespace capsula::scene2d
