// A time-integration method registered from outside the package (TwoStageMethod.hpp) runs
// from a deck through the same integrator and loop as the built-in ones, with its own key,
// and a misspelt method name is answered with the key and the closest registered name.
#include "TestProblems.hpp"
#include "TwoStageMethod.hpp"

#include "capsula/core/Deck.hpp"
#include "capsula/core/Error.hpp"
#include "capsula/core/ParameterDeclaration.hpp"
#include "capsula/testing/ConvergenceOrder.hpp"
#include "capsula/timeint/TimeIntegrationParameters.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

namespace ti = capsula::timeint;
namespace core = capsula::core;

namespace {

ti::MethodRegistry methodsWithTwoStage()
{
  auto methods = ti::builtInMethods();
  ti::testing::registerTwoStageMethod(methods);
  return methods;
}

Teuchos::RCP<Teuchos::ParameterList> validatedDeck(const std::string& timeIntegrationXml,
                                                   const ti::MethodRegistry& methods)
{
  auto valid = Teuchos::rcp(new Teuchos::ParameterList("Capsula"));
  ti::declareTimeIntegrationParameters(core::declareSublist(*valid, "Time integration", "Time stepping"), false,
                                       methods);
  auto deck = core::readDeckFromString("<ParameterList name=\"Capsula\"><ParameterList name=\"Time integration\">" +
                                           timeIntegrationXml + "</ParameterList></ParameterList>",
                                       "deck.xml");
  core::validateDeck(*deck, *valid, "deck.xml");
  return deck;
}

std::string xmlParameter(const std::string& name, const std::string& type, const std::string& value)
{
  return "<Parameter name=\"" + name + "\" type=\"" + type + "\" value=\"" + value + "\"/>";
}

// Error at t = 2 of the TwoStage method with `steps` fixed steps and the given alpha, run
// from a deck; the outputs every 0.5 are counted to show the integrator's loop lands on them.
double twoStageError(const ti::testing::TestProblem& problem, int steps, const std::string& alpha)
{
  const auto methods = methodsWithTwoStage();
  const auto deck =
      validatedDeck(xmlParameter("Method", "string", "TwoStage") + xmlParameter("End time", "double", "2") +
                        xmlParameter("Initial step", "double", std::to_string(2.0 / steps)) +
                        xmlParameter("Second stage time", "double", alpha),
                    methods);
  auto integrator = ti::makeTimeIntegrator(deck->sublist("Time integration"), problem.rhs, methods);
  EXPECT_FALSE(integrator.adaptive()); // its traits ask for fixed steps
  auto state = integrator.start(0.0, problem.y0);
  int outputs = 0;
  integrator.integrate(state, ti::OutputSchedule(0.5),
                       {[&](const ti::IntegrationState&, ti::OutputReason) { ++outputs; }});
  EXPECT_EQ(state.time, 2.0);
  EXPECT_EQ(outputs, 5); // t = 0, 0.5, 1, 1.5, 2
  EXPECT_EQ(state.statistics.acceptedSteps, steps);
  EXPECT_EQ(state.statistics.rhsEvaluations, 2 * steps); // two stages a step
  return ti::testing::maxError(state.y, problem.exact(2.0));
}

} // namespace

TEST(MethodPlugins, TwoStageConvergesAtSecondOrderForEitherStageTime)
{
  for (const std::string alpha : {"1", "0.5"}) {
    for (const auto& problem : {ti::testing::cosine(), ti::testing::rotation()}) {
      std::vector<int> steps;
      std::vector<double> error;
      for (int n = 16; n <= 128; n *= 2) {
        steps.push_back(n);
        error.push_back(twoStageError(problem, n, alpha));
      }
      const double order = capsula::testing::fittedOrder(steps, error);
      std::printf("TwoStage alpha = %s on %s: errors %.3e .. %.3e, order %.3f\n", alpha.c_str(), problem.name.c_str(),
                  error.front(), error.back(), order);
      // Steps of 1/8 to 1/64 on smooth problems are in the asymptotic range: the slope is
      // within 0.1 of 2 (a wrong weight gives order 1; y' = cos t tests the stage time).
      EXPECT_NEAR(order, 2.0, 0.1) << "alpha = " << alpha << " on " << problem.name;
    }
  }
}

TEST(MethodPlugins, TheMethodsKeyReachesIt)
{
  // On y' = cos t, Heun is the trapezoidal rule and alpha = 1/2 the midpoint rule: their
  // global errors are -h^2/12 and +h^2/24 times (f'(2) - f'(0)), a ratio of -2 up to
  // O(h^2) = 1.6% at h = 1/8. A key that did not reach the method would give a ratio of 1.
  const auto problem = ti::testing::cosine();
  const auto methods = methodsWithTwoStage();
  const auto signedError = [&](const std::string& alpha) {
    const auto deck = validatedDeck(
        xmlParameter("Method", "string", "TwoStage") + xmlParameter("End time", "double", "2") +
            xmlParameter("Initial step", "double", "0.125") + xmlParameter("Second stage time", "double", alpha),
        methods);
    auto integrator = ti::makeTimeIntegrator(deck->sublist("Time integration"), problem.rhs, methods);
    auto state = integrator.start(0.0, problem.y0);
    integrator.integrate(state, {}, {});
    return state.y[0] - problem.exact(2.0)[0];
  };
  EXPECT_NEAR(signedError("1") / signedError("0.5"), -2.0, 0.05);
  const auto deck = validatedDeck(xmlParameter("Method", "string", "TwoStage"), methods);
  const auto settings = ti::timeIntegrationSettings(deck->sublist("Time integration"), methods);
  EXPECT_EQ(settings.methodParameters.get<double>("Second stage time"), 1.0); // the declared default
}

TEST(MethodPlugins, AnUnknownMethodNameIsAnsweredWithTheKeyAndTheClosestName)
{
  const auto methods = methodsWithTwoStage();
  try {
    validatedDeck(xmlParameter("Method", "string", "TwoStag"), methods);
    FAIL() << "an unknown method was accepted";
  } catch (const core::InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("Time integration/Method"), std::string::npos) << what;
    EXPECT_NE(what.find("did you mean \"TwoStage\""), std::string::npos) << what;
  }
  ti::TimeIntegrationSettings settings;
  settings.method = "TwoStag";
  try {
    ti::TimeIntegrator integrator(settings, ti::testing::exponentialDecay().rhs, methods);
    FAIL() << "an unknown method was accepted";
  } catch (const core::InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'Time integration/Method' = 'TwoStag'"), std::string::npos) << what;
    EXPECT_NE(what.find("Did you mean 'TwoStage'?"), std::string::npos) << what;
  }
  // Without the plug-in registered the name is unknown.
  settings.method = "TwoStage";
  EXPECT_THROW(ti::TimeIntegrator(settings, ti::testing::exponentialDecay().rhs), core::InputError);
}

TEST(MethodPlugins, AKeyOfAnotherMethodMustKeepItsDefault)
{
  const auto methods = methodsWithTwoStage();
  const auto deck = validatedDeck(
      xmlParameter("Method", "string", "RKF45") + xmlParameter("Second stage time", "double", "0.5"), methods);
  try {
    ti::makeTimeIntegrator(deck->sublist("Time integration"), ti::testing::exponentialDecay().rhs, methods);
    FAIL() << "a key of TwoStage was accepted with RKF45";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'Time integration/Second stage time' = 0.5 applies to Method TwoStage only"),
              std::string::npos)
        << e.what();
  }
}

TEST(MethodPlugins, ANameOrAKeyDeclaredTwiceDifferentlyIsRefused)
{
  auto methods = methodsWithTwoStage();
  EXPECT_THROW(ti::testing::registerTwoStageMethod(methods), core::Error);
  ti::MethodRegistry registry;
  ti::testing::registerTwoStageMethod(registry);
  auto keys = Teuchos::rcp(new Teuchos::ParameterList("Time integration"));
  core::declareReal(*keys, "Second stage time", 0.5, "another default");
  ti::MethodInfo other{
      "another method", keys, {}, [](const ti::TimeIntegrationSettings&, const Teuchos::ParameterList&) {
        return std::unique_ptr<ti::TimeIntegrationMethod>();
      }};
  EXPECT_THROW(registry.add("Other", other), core::Error);
}
