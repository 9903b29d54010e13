#pragma once
// Validators for deck parameters.
//
// Teuchos's own validators produce long, generic messages. These say in one
// phrase what a value must be ("a real number > 0"), so that the deck reader can
// name the key path, the deck file, the offending value and the requirement.
// Each implements Teuchos::ParameterEntryValidator, so Teuchos still calls them
// from validateParametersAndSetDefaults.
#include <Teuchos_ParameterEntryValidator.hpp>

#include <optional>
#include <string>
#include <vector>

namespace capsula::core {

/// A validator that can state its requirement in words.
class DescribedValidator : public Teuchos::ParameterEntryValidator {
public:
  /// E.g. "a real number > 0", "one of: NeoHookean, Skalak".
  virtual std::string requirement() const = 0;
  /// Empty if the entry is acceptable, otherwise why it is not.
  virtual std::string check(const Teuchos::ParameterEntry& entry) const = 0;

  void validate(const Teuchos::ParameterEntry& entry, const std::string& paramName,
                const std::string& sublistName) const override;
  void printDoc(const std::string& docString, std::ostream& out) const override;
  ValidStringsList validStringValues() const override { return Teuchos::null; }
};

/// Bounds on a number; each bound optional and open or closed.
struct Bound {
  double value = 0.0;
  bool inclusive = true;
};

/// A real number within optional bounds.
class RealRangeValidator final : public DescribedValidator {
public:
  RealRangeValidator(std::optional<Bound> lower, std::optional<Bound> upper);
  const std::string getXMLTypeName() const override { return "capsula::RealRange"; }
  std::string requirement() const override;
  std::string check(const Teuchos::ParameterEntry& entry) const override;
  bool accepts(double value) const;

private:
  std::optional<Bound> lower_, upper_;
};

/// An integer within optional closed bounds.
class IntRangeValidator final : public DescribedValidator {
public:
  IntRangeValidator(std::optional<int> lower, std::optional<int> upper);
  const std::string getXMLTypeName() const override { return "capsula::IntRange"; }
  std::string requirement() const override;
  std::string check(const Teuchos::ParameterEntry& entry) const override;

private:
  std::optional<int> lower_, upper_;
};

/// A string from a fixed list (case-sensitive); the message suggests the closest choice.
class ChoiceValidator final : public DescribedValidator {
public:
  explicit ChoiceValidator(std::vector<std::string> choices);
  const std::string getXMLTypeName() const override { return "capsula::Choice"; }
  std::string requirement() const override;
  std::string check(const Teuchos::ParameterEntry& entry) const override;
  ValidStringsList validStringValues() const override;
  const std::vector<std::string>& choices() const { return choices_; }

private:
  std::vector<std::string> choices_;
};

/// An Array(double) of a fixed length (0: any length) whose entries are finite
/// and lie within optional bounds.
class RealArrayValidator final : public DescribedValidator {
public:
  RealArrayValidator(int length, std::optional<Bound> lower, std::optional<Bound> upper);
  const std::string getXMLTypeName() const override { return "capsula::RealArray"; }
  std::string requirement() const override;
  std::string check(const Teuchos::ParameterEntry& entry) const override;

private:
  int length_;
  RealRangeValidator element_;
};

/// Levenshtein distance, used to suggest a key or choice the user probably meant.
std::size_t editDistance(const std::string& a, const std::string& b);

/// The candidate closest to `word`, if it is close enough to be a likely typo.
std::optional<std::string> closestMatch(const std::string& word, const std::vector<std::string>& candidates);

} // namespace capsula::core
