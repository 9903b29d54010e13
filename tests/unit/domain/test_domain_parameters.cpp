// The domain's deck keys: declared with their defaults, read into a Domain and a
// FlowProfile, and refused where the walls and the profile contradict each other.
#include <capsula/core/Deck.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/domain/DomainParameters.hpp>

#include <gtest/gtest.h>

#include <functional>

namespace {

namespace core = capsula::core;
namespace domain = capsula::domain;

// A deck of the domain's keys with `set` applied, validated (defaults filled in).
Teuchos::ParameterList validatedDeck(const std::function<void(Teuchos::ParameterList&)>& set)
{
  Teuchos::ParameterList valid;
  domain::declareDomainParameters(valid);
  Teuchos::ParameterList deck;
  set(deck);
  core::validateDeck(deck, valid, "test deck");
  return deck;
}

std::string refusalOf(const std::function<void(Teuchos::ParameterList&)>& set)
{
  try {
    const auto deck = validatedDeck(set);
    const auto d = domain::readDomain(deck);
    domain::readFlowProfile(deck, d);
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(DomainParameters, DefaultsAreTheThesisDomain)
{
  const auto deck = validatedDeck([](Teuchos::ParameterList&) {});
  const auto d = domain::readDomain(deck);
  EXPECT_TRUE(d.hasLowerWall());
  EXPECT_FALSE(d.hasUpperWall());
  EXPECT_FALSE(d.isPeriodic());
  EXPECT_EQ(domain::readFlowProfile(deck, d).kind(), domain::FlowProfileKind::Shear);
}

TEST(DomainParameters, AChannelPeriodicAlongTheFlowInPoiseuilleFlow)
{
  const auto deck = validatedDeck([](Teuchos::ParameterList& list) {
    list.sublist("Wall").set("Channel height", 12.0);
    list.sublist("Domain").set("Periodic length x", 24.0);
    list.sublist("Flow").set("Profile", std::string("Poiseuille"));
  });
  const auto d = domain::readDomain(deck);
  EXPECT_EQ(d.channelHeight(), 12.0);
  EXPECT_EQ(d.period(domain::flowAxis), 24.0);
  EXPECT_FALSE(d.isPeriodic(domain::vorticityAxis));
  const auto flow = domain::readFlowProfile(deck, d);
  EXPECT_EQ(flow.kind(), domain::FlowProfileKind::Poiseuille);
  EXPECT_DOUBLE_EQ(flow.velocity(6.0), 3.0); // H / 4 on the centre-plane
}

TEST(DomainParameters, ContradictionsAreRefusedNamingTheKeys)
{
  const std::string noLowerWall = refusalOf([](Teuchos::ParameterList& list) {
    list.sublist("Wall").set("Enabled", false);
    list.sublist("Wall").set("Channel height", 5.0);
  });
  EXPECT_NE(noLowerWall.find("'Wall/Channel height' = 5"), std::string::npos) << noLowerWall;
  EXPECT_NE(noLowerWall.find("'Wall/Enabled' = false"), std::string::npos) << noLowerWall;
  const std::string poiseuille =
      refusalOf([](Teuchos::ParameterList& list) { list.sublist("Flow").set("Profile", std::string("Poiseuille")); });
  EXPECT_NE(poiseuille.find("'Flow/Profile' = 'Poiseuille'"), std::string::npos) << poiseuille;
  // The validators refuse negative lengths and unknown profiles, naming the key.
  const std::string negative =
      refusalOf([](Teuchos::ParameterList& list) { list.sublist("Domain").set("Periodic length z", -3.0); });
  EXPECT_NE(negative.find("Periodic length z"), std::string::npos) << negative;
  const std::string unknown =
      refusalOf([](Teuchos::ParameterList& list) { list.sublist("Flow").set("Profile", std::string("Couette")); });
  EXPECT_NE(unknown.find("Profile"), std::string::npos) << unknown;
}

} // namespace
