#pragma once
// A validated tether2d deck for tests: the defaults, small sizes, and overrides.
#include <capsula/core/Deck.hpp>
#include <capsula/scene2d/Tether2DDeck.hpp>

#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

namespace capsula::scene2d::testing {

/// The defaults with `overrides` ("List/Key=value") applied, validated.
inline Teuchos::ParameterList tether2dDeck(const std::vector<std::string>& overrides)
{
  const auto valid = validTether2DParameters();
  Teuchos::ParameterList deck("tether2d");
  for (const auto& assignment : overrides) {
    core::applyOverride(deck, *valid, assignment);
  }
  core::validateDeck(deck, *valid, "test deck");
  return deck;
}

} // namespace capsula::scene2d::testing
