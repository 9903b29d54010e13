#include "capsula/core/DeckValidators.hpp"

#include "capsula/core/Error.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_ParameterEntry.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace capsula::core {

void DescribedValidator::validate(const Teuchos::ParameterEntry& entry, const std::string& paramName,
                                  const std::string& sublistName) const
{
  const std::string why = check(entry);
  if (!why.empty()) {
    throw InputError(message("'", sublistName, "/", paramName, "' ", why));
  }
}

void DescribedValidator::printDoc(const std::string& docString, std::ostream& out) const
{
  out << "# " << docString << "\n# Must be " << requirement() << ".\n";
}

namespace {

std::string describeBound(const Bound& b, bool isLower)
{
  std::ostringstream out;
  out << (isLower ? (b.inclusive ? ">= " : "> ") : (b.inclusive ? "<= " : "< ")) << b.value;
  return out.str();
}

bool satisfies(double v, const std::optional<Bound>& lower, const std::optional<Bound>& upper)
{
  if (!std::isfinite(v)) {
    return false;
  }
  if (lower && (lower->inclusive ? v < lower->value : v <= lower->value)) {
    return false;
  }
  if (upper && (upper->inclusive ? v > upper->value : v >= upper->value)) {
    return false;
  }
  return true;
}

std::string rangeText(const std::optional<Bound>& lower, const std::optional<Bound>& upper)
{
  std::string text;
  if (lower) {
    text += " " + describeBound(*lower, true);
  }
  if (lower && upper) {
    text += " and";
  }
  if (upper) {
    text += " " + describeBound(*upper, false);
  }
  return text;
}

} // namespace

RealRangeValidator::RealRangeValidator(std::optional<Bound> lower, std::optional<Bound> upper)
    : lower_(lower), upper_(upper)
{}

std::string RealRangeValidator::requirement() const
{
  return "a finite real number" + rangeText(lower_, upper_);
}

bool RealRangeValidator::accepts(double value) const
{
  return satisfies(value, lower_, upper_);
}

std::string RealRangeValidator::check(const Teuchos::ParameterEntry& entry) const
{
  if (!entry.isType<double>()) {
    return "must be of type double (" + requirement() + ")";
  }
  const double v = entry.getValue<double>(nullptr);
  if (!accepts(v)) {
    return message("= ", v, " is invalid: it must be ", requirement());
  }
  return {};
}

IntRangeValidator::IntRangeValidator(std::optional<int> lower, std::optional<int> upper) : lower_(lower), upper_(upper)
{}

std::string IntRangeValidator::requirement() const
{
  std::string text = "an integer";
  if (lower_ && upper_) {
    return text + message(" from ", *lower_, " to ", *upper_);
  }
  if (lower_) {
    return text + message(" >= ", *lower_);
  }
  if (upper_) {
    return text + message(" <= ", *upper_);
  }
  return text;
}

std::string IntRangeValidator::check(const Teuchos::ParameterEntry& entry) const
{
  if (!entry.isType<int>()) {
    return "must be of type int (" + requirement() + ")";
  }
  const int v = entry.getValue<int>(nullptr);
  if ((lower_ && v < *lower_) || (upper_ && v > *upper_)) {
    return message("= ", v, " is invalid: it must be ", requirement());
  }
  return {};
}

ChoiceValidator::ChoiceValidator(std::vector<std::string> choices) : choices_(std::move(choices)) {}

std::string ChoiceValidator::requirement() const
{
  std::string text = "one of:";
  for (std::size_t i = 0; i < choices_.size(); ++i) {
    text += (i == 0 ? " " : ", ") + choices_[i];
  }
  return text;
}

std::string ChoiceValidator::check(const Teuchos::ParameterEntry& entry) const
{
  if (!entry.isType<std::string>()) {
    return "must be of type string (" + requirement() + ")";
  }
  const auto& v = entry.getValue<std::string>(nullptr);
  if (std::find(choices_.begin(), choices_.end(), v) != choices_.end()) {
    return {};
  }
  std::string why = "= \"" + v + "\" is invalid: it must be " + requirement();
  if (const auto guess = closestMatch(v, choices_)) {
    why += " (did you mean \"" + *guess + "\"?)";
  }
  return why;
}

Teuchos::ParameterEntryValidator::ValidStringsList ChoiceValidator::validStringValues() const
{
  return Teuchos::rcp(new Teuchos::Array<std::string>(choices_.begin(), choices_.end()));
}

RealArrayValidator::RealArrayValidator(int length, std::optional<Bound> lower, std::optional<Bound> upper)
    : length_(length), element_(lower, upper)
{}

std::string RealArrayValidator::requirement() const
{
  std::string text =
      length_ > 0 ? message("an Array(double) of ", length_, " entries") : std::string("an Array(double)");
  return text + ", each " + element_.requirement();
}

std::string RealArrayValidator::check(const Teuchos::ParameterEntry& entry) const
{
  if (!entry.isType<Teuchos::Array<double>>()) {
    return "must be " + requirement() + ", e.g. {0.0, 2.0, 0.0}";
  }
  const auto& a = entry.getValue<Teuchos::Array<double>>(nullptr);
  if (length_ > 0 && static_cast<int>(a.size()) != length_) {
    return message("has ", a.size(), " entries; it must have ", length_);
  }
  for (Teuchos::Array<double>::size_type i = 0; i < a.size(); ++i) {
    if (!element_.accepts(a[i])) {
      return message("entry ", i, " = ", a[i], " is invalid: each entry must be ", element_.requirement());
    }
  }
  return {};
}

std::size_t editDistance(const std::string& a, const std::string& b)
{
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) {
    row[j] = j;
  }
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      const std::size_t cost = (std::tolower(a[i - 1]) == std::tolower(b[j - 1])) ? 0 : 1;
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + cost});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::optional<std::string> closestMatch(const std::string& word, const std::vector<std::string>& candidates)
{
  std::optional<std::string> best;
  std::size_t bestDistance = std::max<std::size_t>(3, word.size() / 3) + 1;
  for (const auto& c : candidates) {
    const std::size_t d = editDistance(word, c);
    if (d < bestDistance) {
      bestDistance = d;
      best = c;
    }
  }
  return best;
}

} // namespace capsula::core
