#pragma once
// A validated tether2d deck for the run tests: the defaults, small sizes, and overrides.
#include "Tether2DTesting.hpp"

#include <capsula/scene2d/Tether2DDeck.hpp>

#include <string>
#include <vector>

namespace capsula::scene2d::testing {

/// The tether2d defaults with `overrides` ("List/Key=value") applied, validated.
inline Teuchos::ParameterList tether2dDeck(const std::vector<std::string>& overrides)
{
  return scene2d::testing::deckWith(*validTether2DParameters(), overrides);
}

} // namespace capsula::scene2d::testing
