#include "capsula/scene2d/StepInFluid2D.hpp"

#include <capsula/core/Error.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <sstream>

namespace capsula::scene2d {

namespace {

std::string describeNode(int node, double x, double y)
{
  std::ostringstream out;
  out << "node " << node << " at (" << x << ", " << y << ")";
  return out.str();
}

} // namespace

NodeOutsideFluid::NodeOutsideFluid(int node, double x, double y)
  : std::runtime_error(describeNode(node, x, y) + " is on or below the wall y = 0"), node_(node), x_(x), y_(y)
{
}

std::string NodeOutsideFluid::describe() const
{
  return describeNode(node_, x_, y_);
}

int firstNodeOutsideFluid(const std::vector<double>& state)
{
  for (std::size_t i = 1; i < state.size(); i += 2) {
    if (!(state[i] > 0.0)) { // NaN counts as outside as well
      return static_cast<int>(i / 2);
    }
  }
  return -1;
}

void requireNodesInFluid(const std::vector<double>& state)
{
  const int node = firstNodeOutsideFluid(state);
  if (node >= 0) {
    const auto i = static_cast<std::size_t>(node);
    throw NodeOutsideFluid(node, state[2 * i], state[2 * i + 1]);
  }
}

timeint::StepReport stepInFluid(timeint::TimeIntegrator& integrator, timeint::IntegrationState& state, double tStop)
{
  const timeint::TimeIntegrationSettings& settings = integrator.settings();
  for (;;) {
    const timeint::IntegrationState before = state;
    std::string where;
    try {
      const timeint::StepReport report = integrator.step(state, tStop);
      const int node = firstNodeOutsideFluid(state.y);
      if (node < 0) {
        return report;
      }
      const auto i = static_cast<std::size_t>(node);
      where = NodeOutsideFluid(node, state.y[2 * i], state.y[2 * i + 1]).describe() + " after the step";
      const std::int64_t evaluations = state.statistics.rhsEvaluations;
      const std::int64_t rejected = state.statistics.rejectedSteps;
      state = before; // undo the accepted step; its evaluations and rejections did happen
      state.statistics.rhsEvaluations = evaluations;
      state.statistics.rejectedSteps = rejected;
    } catch (const NodeOutsideFluid& outside) {
      // step() left the state at the last accepted one (TimeIntegrator.hpp).
      where = outside.describe() + " in a stage";
    }
    // Fixed steps are the user's choice: nothing to adapt.
    core::require<core::NumericalError>(integrator.adaptive(), "Time integration failed: the cell reaches the wall (",
                                        where, ") in the fixed step from t = ", state.time, " (dt = ",
                                        state.proposedStep, "); use a smaller Time integration/Initial step.");
    // The step that was tried: the proposal, bounded as TimeIntegrator::step bounds it.
    const double tried = std::min({state.proposedStep, settings.maximumStep, tStop - state.time});
    ++state.statistics.rejectedSteps;
    state.proposedStep = 0.5 * tried;
    core::require<core::NumericalError>(
      state.proposedStep >= settings.minimumStep, "Time integration failed: the cell reaches the wall (", where,
      ") at t = ", state.time, " for every step down to ", tried,
      " (Time integration/Minimum step = ", settings.minimumStep, "). The state at t = ", state.time,
      " is the last accepted one.");
  }
}

} // namespace capsula::scene2d
