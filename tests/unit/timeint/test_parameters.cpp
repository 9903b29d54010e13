// The "Time integration" deck sublist: declaration, validation, and building the integrator.
#include "TestProblems.hpp"

#include "capsula/core/Deck.hpp"
#include "capsula/core/Error.hpp"
#include "capsula/core/ParameterDeclaration.hpp"
#include "capsula/timeint/TimeIntegrationParameters.hpp"

#include <gtest/gtest.h>

#include <string>

namespace ti = capsula::timeint;
namespace core = capsula::core;

namespace {

Teuchos::RCP<const Teuchos::ParameterList> validList()
{
  auto valid = Teuchos::rcp(new Teuchos::ParameterList("Capsula"));
  ti::declareTimeIntegrationParameters(core::declareSublist(*valid, "Time integration", "Time stepping"));
  return valid;
}

Teuchos::RCP<Teuchos::ParameterList> validatedDeck(const std::string& timeIntegrationXml)
{
  auto deck = core::readDeckFromString("<ParameterList name=\"Capsula\"><ParameterList name=\"Time integration\">" +
                                           timeIntegrationXml + "</ParameterList></ParameterList>",
                                       "deck.xml");
  core::validateDeck(*deck, *validList(), "deck.xml");
  return deck;
}

} // namespace

TEST(TimeIntegrationParameters, DefaultsAreTheDocumentedOnes)
{
  const auto deck = validatedDeck("");
  const auto s = ti::timeIntegrationSettings(deck->sublist("Time integration"));
  EXPECT_EQ(s.method, "RKF45");
  EXPECT_TRUE(s.adaptive);
  EXPECT_FALSE(s.methodParameters.get<bool>("Local extrapolation"));
  EXPECT_EQ(s.tolerance, 1e-6);
  EXPECT_EQ(s.methodParameters.get<double>("Relative tolerance"), 0.0);
  EXPECT_EQ(s.initialStep, 1e-3);
  EXPECT_EQ(s.minimumStep, 1e-12);
  EXPECT_EQ(s.maximumStep, 1.0);
  EXPECT_EQ(s.endTime, 10.0);
  EXPECT_EQ(s.steadyCriterion, ti::SteadyStateCriterion::Off);
}

TEST(TimeIntegrationParameters, DeckValuesReachTheIntegrator)
{
  const auto deck = validatedDeck(R"(
    <Parameter name="End time" type="double" value="2.5"/>
    <Parameter name="Method" type="string" value="DormandPrince45"/>
    <Parameter name="Tolerance" type="double" value="1e-9"/>
    <Parameter name="Relative tolerance" type="double" value="1e-7"/>
    <Parameter name="Steady tolerance" type="double" value="1e-7"/>
    <Parameter name="Steady criterion" type="string" value="L2Change"/>)");
  const auto problem = ti::testing::exponentialDecay();
  auto integrator = ti::makeTimeIntegrator(deck->sublist("Time integration"), problem.rhs);
  const auto& s = integrator.settings();
  EXPECT_EQ(s.method, "DormandPrince45");
  EXPECT_EQ(s.tolerance, 1e-9);
  EXPECT_EQ(s.methodParameters.get<double>("Relative tolerance"), 1e-7);
  EXPECT_EQ(s.steadyCriterion, ti::SteadyStateCriterion::L2Change);
  auto state = integrator.start(0.0, problem.y0);
  EXPECT_EQ(integrator.activeMethodName(state), "DormandPrince45");
  integrator.integrate(state, {}, {});
  EXPECT_EQ(state.time, 2.5);
  EXPECT_NEAR(state.y[0], std::exp(-2.5), 1e-8); // tolerance 1e-9 per step, ~20 steps
}

TEST(TimeIntegrationParameters, RK4RunsWithFixedSteps)
{
  const auto deck = validatedDeck(R"(
    <Parameter name="End time" type="double" value="1"/>
    <Parameter name="Method" type="string" value="RK4"/>
    <Parameter name="Initial step" type="double" value="0.125"/>)");
  const auto problem = ti::testing::exponentialDecay();
  auto integrator = ti::makeTimeIntegrator(deck->sublist("Time integration"), problem.rhs);
  EXPECT_FALSE(integrator.adaptive());
  auto state = integrator.start(0.0, problem.y0);
  integrator.integrate(state, {}, {});
  EXPECT_EQ(state.statistics.acceptedSteps, 8);
  EXPECT_EQ(state.statistics.rhsEvaluations, 32);
}

TEST(TimeIntegrationParameters, BadValuesAreNamed)
{
  try {
    validatedDeck(R"(<Parameter name="Method" type="string" value="RKF54"/>)");
    FAIL() << "an unknown method was accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Time integration/Method"), std::string::npos) << e.what();
  }
  EXPECT_THROW(validatedDeck(R"(<Parameter name="Tolerance" type="double" value="0"/>)"), core::InputError);
  const auto deck = validatedDeck(R"(<Parameter name="Minimum step" type="double" value="0.01"/>
                                     <Parameter name="Initial step" type="double" value="0.001"/>)");
  const auto problem = ti::testing::exponentialDecay();
  try {
    ti::makeTimeIntegrator(deck->sublist("Time integration"), problem.rhs);
    FAIL() << "Initial step < Minimum step was accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Time integration/Initial step"), std::string::npos) << e.what();
  }
}
