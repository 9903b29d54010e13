#pragma once
// Steady-state detection: the run has reached equilibrium when the state stops moving.
// Two measures, compared after every accepted step with a tolerance:
//   MaxChangeRate: |y_{n+1} - y_n|_inf / h     (fastest node coordinate speed; independent
//                                               of the step size and of the number of nodes)
//   L2Change:      |y_{n+1} - y_n|_2           (the thesis's 2D criterion, Fig. 4.4:
//                                               "L2-norm of the difference in position
//                                               between successive time steps < 1e-7";
//                                               it depends on the step size and grows
//                                               like sqrt(number of nodes))
#include "capsula/timeint/VectorNorms.hpp"

#include <cstddef>
#include <string>

namespace capsula::timeint {

enum class SteadyStateCriterion { Off, MaxChangeRate, L2Change };

/// "Off", "MaxChangeRate", "L2Change" (the deck spelling).
std::string toString(SteadyStateCriterion criterion);
/// The inverse of toString; throws core::InputError naming the word.
SteadyStateCriterion steadyStateCriterionFromString(const std::string& word);

/// The measure of the criterion for one accepted step from yOld to yNew of size h
/// (0 for Off).
inline double steadyStateMeasure(SteadyStateCriterion criterion, const double* yOld, const double* yNew, std::size_t n,
                                 double h)
{
  switch (criterion) {
  case SteadyStateCriterion::MaxChangeRate:
    return maxDifference(yNew, yOld, n) / h;
  case SteadyStateCriterion::L2Change:
    return euclideanDifference(yNew, yOld, n);
  case SteadyStateCriterion::Off:
    break;
  }
  return 0.0;
}

} // namespace capsula::timeint
