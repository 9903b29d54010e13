#pragma once
// Named Green's functions of one dimension: for each deck name ('Operator/Kernel') the
// factory that builds its operator, the fluid domain it is for and its own deck settings.
// KernelRegistry (3D) and scene2d::KernelRegistry2D are catalogues of their dimension's factories;
// the deck side (KernelChoice.hpp) needs only the KernelInfo, whatever the dimension.
#include <capsula/operators/RegisteredNames.hpp>

#include <capsula/core/Error.hpp>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace capsula::operators {

/// The walls of the fluid a Green's function describes; 'Wall/Enabled' and
/// 'Wall/Channel height' must agree with it (domain/Domain.hpp).
enum class FluidDomain {
  Unbounded, ///< no boundary: Wall/Enabled = false
  AboveWall, ///< the half space y > 0 over the no-slip plane y = 0: Wall/Enabled = true
  Channel    ///< the layer 0 < y < H between two no-slip planes: Wall/Channel height = H > 0
};

/// What the deck knows about a registered kernel.
struct KernelInfo {
  std::string description; ///< one line for the deck reference
  FluidDomain domain = FluidDomain::Unbounded;
  /// The kernel's own keys (defaults, validators, doc strings), declared as the deck
  /// sublist 'Operator/<name>' and handed to the factory; null: the kernel has none.
  Teuchos::RCP<const Teuchos::ParameterList> validParameters;
  /// true: the kernel is periodic along x and z (the walls' directions), with the periods
  /// the deck gives ('Domain/Periodic length x', 'z'; both set); false: it serves only
  /// domains without a periodic direction.
  bool periodic = false;
};

template <class Factory>
class KernelCatalogue {
public:
  /// Registers `factory` under `name`. Throws core::InputError if the name is taken,
  /// empty or "Auto" (the deck's automatic choice), or the factory is empty.
  void add(const std::string& name, KernelInfo info, Factory factory)
  {
    core::require<core::InputError>(!name.empty() && name != "Auto", "A kernel cannot be registered as '", name,
                                    "' (empty, or the deck's automatic choice).");
    core::require<core::InputError>(!contains(name), "A kernel named '", name, "' is registered already.");
    core::require<core::InputError>(static_cast<bool>(factory), "The kernel '", name, "' has no factory.");
    infos_.emplace(name, std::move(info));
    factories_.emplace(name, std::move(factory));
  }
  /// add() for a kernel of an unbounded fluid without settings of its own.
  void add(const std::string& name, const std::string& description, Factory factory)
  {
    add(name, KernelInfo{description, FluidDomain::Unbounded, Teuchos::null}, std::move(factory));
  }

  bool contains(const std::string& name) const { return infos_.count(name) != 0; }
  /// Registered names, sorted (the choices of 'Operator/Kernel' besides Auto).
  std::vector<std::string> names() const
  {
    std::vector<std::string> result;
    for (const auto& entry : infos_) {
      result.push_back(entry.first);
    }
    return result;
  }
  /// Throws core::InputError naming the registered kernels if there is none by `name`.
  const KernelInfo& info(const std::string& name) const
  {
    requireRegistered("Green's function kernel", name, names());
    return infos_.at(name);
  }
  const std::string& description(const std::string& name) const { return info(name).description; }
  /// Every kernel's info by name (what the deck declarations need).
  const std::map<std::string, KernelInfo>& infos() const { return infos_; }

protected:
  const Factory& factory(const std::string& name) const
  {
    requireRegistered("Green's function kernel", name, names());
    return factories_.at(name);
  }

private:
  std::map<std::string, KernelInfo> infos_;
  std::map<std::string, Factory> factories_;
};

} // namespace capsula::operators
