#pragma once
// Deck name ('Operator/Summation') -> far-field back-end of the regular quadrature sums.
// "Direct" (the operators' own exact, vectorised sums) is built in; a fast-summation
// library registers its back-end with the keys of its own deck sublist
// 'Operator/<name>' (fastsum's "Treecode", TreecodeRegistration.hpp). The application owns
// the registry (docs/extending.md).
#include <capsula/operators/FarFieldBackEnd.hpp>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace capsula::operators {

/// Builds the back-end from its settings ('Operator/<name>', defaults filled in; empty
/// without settings); null means the direct sums.
using FarFieldFactory = std::function<std::shared_ptr<const FarFieldBackEnd>(const Teuchos::ParameterList& settings)>;

class SummationRegistry {
public:
  /// Registers `factory` under `name` with a description for the deck reference and the
  /// keys of its sublist (`validParameters`, null: none). Throws core::InputError if the
  /// name is taken or empty, or the factory is empty.
  void add(const std::string& name, const std::string& description, FarFieldFactory factory,
           Teuchos::RCP<const Teuchos::ParameterList> validParameters = Teuchos::null);

  bool contains(const std::string& name) const { return entries_.count(name) != 0; }
  /// Registered names, sorted (the choices of 'Operator/Summation').
  std::vector<std::string> names() const;
  /// These three throw core::InputError naming the registered back-ends for an unknown name.
  const std::string& description(const std::string& name) const;
  /// The keys of the back-end's sublist; null if it has none.
  const Teuchos::RCP<const Teuchos::ParameterList>& validParameters(const std::string& name) const;
  /// The back-end `name` with `settings` (its sublist; missing keys take their defaults).
  std::shared_ptr<const FarFieldBackEnd> create(const std::string& name, const Teuchos::ParameterList& settings) const;

private:
  struct Entry {
    std::string description;
    FarFieldFactory factory;
    Teuchos::RCP<const Teuchos::ParameterList> validParameters;
  };
  const Entry& entry(const std::string& name) const;
  std::map<std::string, Entry> entries_;
};

/// A registry holding "Direct".
SummationRegistry builtInSummations();

/// Declares 'Summation' in `operatorList` (default Direct, choices and doc strings from
/// `summations`) and the sublist of each back-end with settings.
void declareSummationParameters(Teuchos::ParameterList& operatorList, const SummationRegistry& summations);

/// The back-end a validated "Operator" list selects (null for Direct; a list without
/// 'Summation' means Direct).
std::shared_ptr<const FarFieldBackEnd> readFarFieldBackEnd(const Teuchos::ParameterList& operatorList,
                                                           const SummationRegistry& summations);

} // namespace capsula::operators
