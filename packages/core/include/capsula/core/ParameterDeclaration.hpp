#pragma once
// Declaring deck parameters.
//
// The component that reads a parameter declares it here: name, default value,
// a doc string and a validator. The declarations form the "valid parameter
// list" against which decks are checked (Deck.hpp), and from which
// `--print-defaults` and the deck reference in docs/ are generated.
#include "capsula/core/DeckValidators.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_ParameterList.hpp>

#include <optional>
#include <string>
#include <vector>

namespace capsula::core {

/// Bound helpers for readable declarations: greaterThan(0.0), atLeast(1.0), ...
inline Bound greaterThan(double v)
{
  return {v, false};
}
inline Bound atLeast(double v)
{
  return {v, true};
}
inline Bound lessThan(double v)
{
  return {v, false};
}
inline Bound atMost(double v)
{
  return {v, true};
}

void declareReal(Teuchos::ParameterList& list, const std::string& name, double defaultValue, const std::string& doc,
                 std::optional<Bound> lower = std::nullopt, std::optional<Bound> upper = std::nullopt);

void declareInt(Teuchos::ParameterList& list, const std::string& name, int defaultValue, const std::string& doc,
                std::optional<int> lower = std::nullopt, std::optional<int> upper = std::nullopt);

void declareBool(Teuchos::ParameterList& list, const std::string& name, bool defaultValue, const std::string& doc);

/// A free-form string (file names, labels).
void declareString(Teuchos::ParameterList& list, const std::string& name, const std::string& defaultValue,
                   const std::string& doc);

/// A string restricted to `choices`.
void declareChoice(Teuchos::ParameterList& list, const std::string& name, const std::string& defaultValue,
                   const std::vector<std::string>& choices, const std::string& doc);

/// An Array(double) of `length` entries (0: any length).
void declareRealArray(Teuchos::ParameterList& list, const std::string& name, const std::vector<double>& defaultValue,
                      int length, const std::string& doc, std::optional<Bound> lower = std::nullopt,
                      std::optional<Bound> upper = std::nullopt);

/// A documented sublist (created if absent).
Teuchos::ParameterList& declareSublist(Teuchos::ParameterList& list, const std::string& name, const std::string& doc);

} // namespace capsula::core
