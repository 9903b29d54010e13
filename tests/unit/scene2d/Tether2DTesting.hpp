#pragma once
// A validated deck of the 2D model for tests: the defaults, small sizes, and overrides.
#include <capsula/core/Deck.hpp>
#include <capsula/scene2d/ModelParameters2D.hpp>

#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

namespace capsula::scene2d::testing {

/// `valid`'s defaults with `overrides` ("List/Key=value") applied, validated.
inline Teuchos::ParameterList deckWith(const Teuchos::ParameterList& valid, const std::vector<std::string>& overrides)
{
  Teuchos::ParameterList deck(valid.name());
  for (const auto& assignment : overrides) {
    core::applyOverride(deck, valid, assignment);
  }
  core::validateDeck(deck, valid, "test deck");
  return deck;
}

/// The model's keys (no Time integration, no Output) with `overrides` applied, validated.
inline Teuchos::ParameterList modelDeck2D(const std::vector<std::string>& overrides)
{
  Teuchos::ParameterList valid("tether2d");
  declareModelParameters2D(valid);
  return deckWith(valid, overrides);
}

} // namespace capsula::scene2d::testing
