// The time loop's observers (TimeIntegrator::integrate with IntegrationObserver): event
// times the steps land on, changes of the state after a step, stops after a step or at an
// output, and output times given by the run.
#include "TestProblems.hpp"

#include "capsula/timeint/TimeIntegrator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace ti = capsula::timeint;

namespace {

ti::TimeIntegrationSettings fixedSteps(double step, double endTime)
{
  ti::TimeIntegrationSettings s;
  s.method = "RK4";
  s.adaptive = false;
  s.initialStep = step;
  s.endTime = endTime;
  return s;
}

/// Records what integrate() shows it, lands on one event time, and stops where told.
class Recorder final : public ti::IntegrationObserver {
public:
  double event = std::numeric_limits<double>::infinity();
  std::int64_t stopAfterStep = -1; ///< accepted steps after which afterStep says Stop
  int stopAtOutput = -1;           ///< number of the output at which atOutput says Stop
  std::vector<double> stepTimes, outputTimes;
  std::vector<bool> stepsAtOutputTimes;
  std::vector<ti::OutputReason> reasons;

  double nextEvent(const ti::IntegrationState&) override { return event; }
  ti::ObserverVerdict afterStep(ti::IntegrationState& state, const ti::StepReport&, bool atOutputTime) override
  {
    stepTimes.push_back(state.time);
    stepsAtOutputTimes.push_back(atOutputTime);
    return state.statistics.acceptedSteps == stopAfterStep ? ti::ObserverVerdict::Stop : ti::ObserverVerdict::Continue;
  }
  ti::ObserverVerdict atOutput(const ti::IntegrationState& state, ti::OutputReason reason) override
  {
    outputTimes.push_back(state.time);
    reasons.push_back(reason);
    return static_cast<int>(outputTimes.size()) == stopAtOutput + 1 ? ti::ObserverVerdict::Stop
                                                                    : ti::ObserverVerdict::Continue;
  }
};

} // namespace

TEST(IntegrationObservers, StepsLandOnEventsAndOutputsAndSeeWhichIsWhich)
{
  const auto problem = ti::testing::exponentialDecay();
  ti::TimeIntegrator integrator(fixedSteps(0.3, 1.0), problem.rhs);
  auto state = integrator.start(0.0, problem.y0);
  Recorder recorder;
  recorder.event = 0.45; // between the steps at 0.3 and 0.6: a step is cut to land on it
  const auto stop = integrator.integrate(state, ti::OutputSchedule(0.5), {&recorder});
  EXPECT_EQ(stop, ti::StopReason::EndTime);
  // Steps of 0.3 from 0, cut at the event 0.45 and the outputs 0.5 and 1 (exact landings).
  const std::vector<double> steps{0.3, 0.45, 0.5, 0.8, 1.0};
  ASSERT_EQ(recorder.stepTimes.size(), steps.size());
  for (std::size_t k = 0; k < steps.size(); ++k) {
    EXPECT_DOUBLE_EQ(recorder.stepTimes[k], steps[k]) << "step " << k;
  }
  EXPECT_EQ(recorder.stepTimes[1], 0.45); // bit for bit on the event
  EXPECT_EQ(recorder.stepsAtOutputTimes, (std::vector<bool>{false, false, true, false, true}));
  EXPECT_EQ(recorder.outputTimes, (std::vector<double>{0.0, 0.5, 1.0}));
  EXPECT_EQ(recorder.reasons.back(), ti::OutputReason::End);
}

TEST(IntegrationObservers, AStopAfterAStepEndsTheIntegrationWithoutItsOutput)
{
  const auto problem = ti::testing::exponentialDecay();
  ti::TimeIntegrator integrator(fixedSteps(0.25, 2.0), problem.rhs);
  auto state = integrator.start(0.0, problem.y0);
  Recorder recorder;
  recorder.stopAfterStep = 2; // t = 0.5, an output time
  EXPECT_EQ(integrator.integrate(state, ti::OutputSchedule(0.5), {&recorder}), ti::StopReason::Requested);
  EXPECT_EQ(state.time, 0.5);
  EXPECT_EQ(recorder.outputTimes, std::vector<double>{0.0}); // the start only
  EXPECT_EQ(state.nextOutput, 1);                            // output 1 not taken
}

TEST(IntegrationObservers, AStopAtAnOutputEndsTheIntegrationAfterIt)
{
  const auto problem = ti::testing::exponentialDecay();
  ti::TimeIntegrator integrator(fixedSteps(0.25, 2.0), problem.rhs);
  auto state = integrator.start(0.0, problem.y0);
  Recorder first, second;
  first.stopAtOutput = 2; // at t = 1
  EXPECT_EQ(integrator.integrate(state, ti::OutputSchedule(0.5), {&first, &second}), ti::StopReason::Requested);
  EXPECT_EQ(state.time, 1.0);
  // Every observer saw that output, the later one too.
  EXPECT_EQ(second.outputTimes, (std::vector<double>{0.0, 0.5, 1.0}));
  EXPECT_EQ(state.nextOutput, 3);
}

TEST(IntegrationObservers, AChangeOfTheStateAfterAStepIsWhatTheNextStepStartsFrom)
{
  // y' = -y with y halved after every step: y(0.4) = e^-0.4 / 2^4 to the RK4 error.
  class Halver final : public ti::IntegrationObserver {
  public:
    ti::ObserverVerdict afterStep(ti::IntegrationState& state, const ti::StepReport&, bool) override
    {
      state.y[0] *= 0.5;
      ti::stateChangedOutside(state);
      return ti::ObserverVerdict::Continue;
    }
  } halver;
  const auto problem = ti::testing::exponentialDecay();
  ti::TimeIntegrator integrator(fixedSteps(0.1, 0.4), problem.rhs);
  auto state = integrator.start(0.0, problem.y0);
  integrator.integrate(state, {}, {&halver});
  // RK4 on y' = -y errs by h^5 / 120 = 8e-8 relative per step of 0.1, 3e-7 over four: 1e-6
  // relative allows for that; without the halving y would be 16 times larger.
  const double expected = problem.y0[0] * std::exp(-0.4) / 16.0;
  EXPECT_NEAR(state.y[0], expected, 1e-6 * expected);
}

TEST(IntegrationObservers, OutputTimesGivenByTheRunAndItsEndTime)
{
  // A stage timed from origin 1 in units of 2: output k at 1 + 2 (0.3 k), the end at 1 + 2.
  const auto problem = ti::testing::exponentialDecay();
  ti::TimeIntegrator integrator(fixedSteps(0.25, 100.0), problem.rhs);
  auto state = integrator.start(1.0, problem.y0);
  ti::OutputSchedule schedule;
  schedule.endTime = 1.0 + 2.0 * 1.0;
  schedule.times = [](std::int64_t k) { return std::min(1.0 + 2.0 * (0.3 * static_cast<double>(k)), 3.0); };
  Recorder recorder;
  EXPECT_EQ(integrator.integrate(state, schedule, {&recorder}), ti::StopReason::EndTime);
  const std::vector<double> expected{1.0, 1.0 + 2.0 * 0.3, 1.0 + 2.0 * 0.6, 1.0 + 2.0 * (0.3 * 3.0), 3.0};
  EXPECT_EQ(recorder.outputTimes, expected); // bit for bit: the steps land on them
  EXPECT_EQ(state.time, 3.0);
}
