#pragma once
// Small validated decks for the scene tests (level-0/1 spheres), and the scene one of them
// describes. The run tests add the keys of a run (run/SceneRunFixture.hpp).
#include <capsula/core/Deck.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>
#include <capsula/operators/KernelRegistry.hpp>
#include <capsula/operators/OperatorParameters.hpp>
#include <capsula/scene/Scene.hpp>
#include <capsula/scene/SceneDescription.hpp>
#include <capsula/scene/SceneParameters.hpp>
#include <capsula/scene/StiffSolverParameters.hpp>

#include <Tpetra_Core.hpp>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <string>
#include <vector>

namespace capsula::scene::testing {

/// An Array(double) deck value.
inline Teuchos::Array<double> realArray(const std::vector<double>& values)
{
  return Teuchos::Array<double>(values.begin(), values.end());
}

/// A deck with one sphere of the given mesh level at height `height` (centre y), wall on
/// or off, not validated yet.
inline Teuchos::RCP<Teuchos::ParameterList> sphereDeck(int level, double height, bool wall)
{
  auto deck = Teuchos::rcp(new Teuchos::ParameterList("test"));
  deck->sublist("Flow").set("Capillary number", 0.3);
  deck->sublist("Wall").set("Enabled", wall);
  auto& cell = deck->sublist("Cells").sublist("Cell 0");
  cell.set("Center", realArray({0.0, height, 0.0}));
  cell.set("Mesh level", level);
  // The thesis practice (no adaptive near-singular integration) keeps the tests fast.
  deck->sublist("Discretisation").set("Near-singular distance", 0.0);
  return deck;
}

/// The keys of the physical model (what a Scene reads) for `deck`.
inline Teuchos::RCP<const Teuchos::ParameterList> validModelParameters(const Teuchos::ParameterList& deck)
{
  auto valid = Teuchos::rcp(new Teuchos::ParameterList("test"));
  declareSceneParameters(*valid, deck);
  operators::declareOperatorParameters(*valid);
  declareStiffSolverParameters(core::declareSublist(valid->sublist("Solver"), "Stiff", "The stiff solves."));
  declareMeshEvolutionParameters(*valid);
  return valid;
}

/// sphereDeck, the other keys at their defaults unless `tweak` changes them. Validated.
template <typename Tweak>
Teuchos::RCP<Teuchos::ParameterList> smallDeck(int level, double height, bool wall, Tweak&& tweak)
{
  auto deck = sphereDeck(level, height, wall);
  tweak(*deck);
  core::validateDeck(*deck, *validModelParameters(*deck), "test deck");
  return deck;
}

inline Teuchos::RCP<Teuchos::ParameterList> smallDeck(int level, double height, bool wall)
{
  return smallDeck(level, height, wall, [](Teuchos::ParameterList&) {});
}

/// The scene a validated deck describes, with the built-in kernels, on the default
/// communicator.
inline Scene makeScene(const Teuchos::ParameterList& deck)
{
  static const auto kernels = operators::builtInKernels();
  return Scene(describeScene(deck), deck, Tpetra::getDefaultComm(), kernels);
}

/// The message of the core::InputError that building the scene of a level-1 sphere at height
/// 1.6 with `tweak` throws, or "" if it builds.
template <typename Tweak>
std::string sceneRefusal(Tweak&& tweak, bool wall = true)
{
  try {
    makeScene(*smallDeck(1, 1.6, wall, tweak));
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "";
}

} // namespace capsula::scene::testing
