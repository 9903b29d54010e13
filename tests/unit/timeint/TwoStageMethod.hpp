#pragma once
// A time-integration method registered from outside the timeint package, the worked example
// of docs/extending.md: the explicit two-stage Runge-Kutta family of order 2,
//
//   k1 = f(t, y),   k2 = f(t + alpha h, y + alpha h k1),
//   y_new = y + h ((1 - 1/(2 alpha)) k1 + 1/(2 alpha) k2),
//
// (alpha = 1: Heun's method, alpha = 1/2: the explicit midpoint rule), with fixed steps of
// 'Time integration/Initial step'. alpha is its one key of its own,
// 'Time integration/Second stage time'.
#include "capsula/timeint/MethodRegistry.hpp"

namespace capsula::timeint::testing {

/// Registers "TwoStage" with its key 'Second stage time' (default 1, in (0, 1]).
void registerTwoStageMethod(MethodRegistry& registry);

} // namespace capsula::timeint::testing
