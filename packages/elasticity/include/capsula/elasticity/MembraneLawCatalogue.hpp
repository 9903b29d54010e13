#pragma once
// Named membrane laws of one dimension: for each deck name ('Membrane law') the factory
// that builds the law, a one-line description and the law's own deck keys (defaults,
// validators, doc strings). MembraneLawRegistry (3D surfaces, MembraneLaw) and
// scene2d::MembraneLawRegistry2D (contours, MembraneLaw2D) are catalogues of their dimension's
// laws; the deck side (MembraneLawChoice.hpp) needs only the MembraneLawInfo. Nothing
// global: the program owns the registry and decides what it holds (docs/extending.md).
#include <capsula/core/Error.hpp>
#include <capsula/core/RegisteredNames.hpp>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace capsula::elasticity {

/// What the deck knows about a registered law.
struct MembraneLawInfo {
  std::string description; ///< one line for the deck reference
  /// The law's own keys, declared beside 'Membrane law' in the cell's sublist and handed to
  /// the factory with their defaults filled in; null: the law has none.
  Teuchos::RCP<const Teuchos::ParameterList> validParameters;
};

/// The kind of entry in the registries' messages.
inline const char* const membraneLawKind = "membrane law";

template <class Law>
class MembraneLawCatalogue {
public:
  /// Builds the law with the modulus that scales its tensions (3D: the cell's shear modulus
  /// G; 2D: the elastic modulus E) and its own keys, defaults filled in.
  using Factory = std::function<std::unique_ptr<Law>(double modulus, const Teuchos::ParameterList& settings)>;

  /// Registers `factory` under `name`. Throws core::InputError if the name is empty or
  /// taken, or the factory is empty.
  void add(const std::string& name, MembraneLawInfo info, Factory factory)
  {
    core::require<core::InputError>(!name.empty(), "A membrane law cannot be registered without a name.");
    core::require<core::InputError>(!contains(name), "A membrane law named '", name, "' is registered already.");
    core::require<core::InputError>(static_cast<bool>(factory), "The membrane law '", name, "' has no factory.");
    infos_.emplace(name, std::move(info));
    factories_.emplace(name, std::move(factory));
  }

  bool contains(const std::string& name) const { return infos_.count(name) != 0; }
  /// Registered names, sorted (the choices of 'Membrane law').
  std::vector<std::string> names() const
  {
    std::vector<std::string> result;
    for (const auto& entry : infos_) {
      result.push_back(entry.first);
    }
    return result;
  }
  /// Throws core::InputError naming the registered laws if there is none by `name`.
  const MembraneLawInfo& info(const std::string& name) const
  {
    core::requireRegistered(membraneLawKind, name, names());
    return infos_.at(name);
  }
  /// Every law's info by name (what the deck declarations need).
  const std::map<std::string, MembraneLawInfo>& infos() const { return infos_; }

  /// The law `name` with modulus `modulus` and the keys `settings` (those it leaves out take
  /// their defaults). Throws core::InputError naming the registered laws (and the closest
  /// one) for an unknown name, and naming the key for a key the law does not declare.
  std::unique_ptr<Law> create(const std::string& name, double modulus,
                              const Teuchos::ParameterList& settings = Teuchos::ParameterList()) const
  {
    const MembraneLawInfo& lawInfo = info(name);
    Teuchos::ParameterList filled;
    if (!lawInfo.validParameters.is_null()) {
      filled = *lawInfo.validParameters;
    }
    for (auto it = settings.begin(); it != settings.end(); ++it) {
      core::require<core::InputError>(filled.isParameter(settings.name(it)), "The membrane law '", name,
                                      "' has no key '", settings.name(it), "'.");
      filled.setEntry(settings.name(it), settings.entry(it));
    }
    return factories_.at(name)(modulus, filled);
  }

private:
  std::map<std::string, MembraneLawInfo> infos_;
  std::map<std::string, Factory> factories_;
};

} // namespace capsula::elasticity
