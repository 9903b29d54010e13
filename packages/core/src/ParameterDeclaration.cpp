#include "capsula/core/ParameterDeclaration.hpp"

#include "capsula/core/Error.hpp"

namespace capsula::core {

void declareReal(Teuchos::ParameterList& list, const std::string& name, double defaultValue, const std::string& doc,
                 std::optional<Bound> lower, std::optional<Bound> upper)
{
  auto validator = Teuchos::rcp(new RealRangeValidator(lower, upper));
  require(validator->accepts(defaultValue), "internal: default of '", name, "' violates its own range (",
          validator->requirement(), ")");
  list.set(name, defaultValue, doc, validator);
}

void declareInt(Teuchos::ParameterList& list, const std::string& name, int defaultValue, const std::string& doc,
                std::optional<int> lower, std::optional<int> upper)
{
  list.set(name, defaultValue, doc, Teuchos::rcp(new IntRangeValidator(lower, upper)));
}

void declareBool(Teuchos::ParameterList& list, const std::string& name, bool defaultValue, const std::string& doc)
{
  list.set(name, defaultValue, doc);
}

void declareString(Teuchos::ParameterList& list, const std::string& name, const std::string& defaultValue,
                   const std::string& doc)
{
  list.set(name, defaultValue, doc);
}

void declareChoice(Teuchos::ParameterList& list, const std::string& name, const std::string& defaultValue,
                   const std::vector<std::string>& choices, const std::string& doc)
{
  require(std::find(choices.begin(), choices.end(), defaultValue) != choices.end(), "internal: default of '", name,
          "' is not one of its choices");
  list.set(name, defaultValue, doc, Teuchos::rcp(new ChoiceValidator(choices)));
}

void declareRealArray(Teuchos::ParameterList& list, const std::string& name, const std::vector<double>& defaultValue,
                      int length, const std::string& doc, std::optional<Bound> lower, std::optional<Bound> upper)
{
  list.set(name, Teuchos::Array<double>(defaultValue.begin(), defaultValue.end()), doc,
           Teuchos::rcp(new RealArrayValidator(length, lower, upper)));
}

Teuchos::ParameterList& declareSublist(Teuchos::ParameterList& list, const std::string& name, const std::string& doc)
{
  return list.sublist(name, false, doc);
}

} // namespace capsula::core
