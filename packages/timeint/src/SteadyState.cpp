#include "capsula/timeint/SteadyState.hpp"

#include "capsula/core/Error.hpp"

namespace capsula::timeint {

std::string toString(SteadyStateCriterion criterion)
{
  switch (criterion) {
  case SteadyStateCriterion::Off:
    return "Off";
  case SteadyStateCriterion::MaxChangeRate:
    return "MaxChangeRate";
  case SteadyStateCriterion::L2Change:
    return "L2Change";
  }
  return "Off";
}

SteadyStateCriterion steadyStateCriterionFromString(const std::string& word)
{
  for (const auto c :
       {SteadyStateCriterion::Off, SteadyStateCriterion::MaxChangeRate, SteadyStateCriterion::L2Change}) {
    if (word == toString(c)) {
      return c;
    }
  }
  throw core::InputError("Unknown steady-state criterion '" + word + "': use one of Off, MaxChangeRate, L2Change.");
}

} // namespace capsula::timeint
