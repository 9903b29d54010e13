// Operator libraries that plug in: a kernel registered outside the operators package
// (ScaledStokesletKernel.hpp), chosen and configured by the deck ('Operator/Kernel',
// 'Operator/ScaledFreeSpace'), runs through the scene as the built-in ones do; the deck
// rejects unknown kernels and back-ends, and kernels for the other fluid domain.
#include "ScaledStokesletKernel.hpp"
#include "SceneTestDecks.hpp"

#include <capsula/core/Deck.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/testing/InputErrorMessage.hpp>
#include <capsula/operators/KernelChoice.hpp>
#include <capsula/run/OperatorLibraries.hpp>
#include <capsula/run/SceneRunDeck.hpp>
#include <capsula/scene/Scene.hpp>
#include <capsula/scene/SceneDescription.hpp>

#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <typeindex>
#include <vector>

namespace capsula::run {
namespace {

using capsula::testing::inputErrorMessage;

OperatorLibraries librariesWithToyKernel()
{
  OperatorLibraries libraries = standardOperatorLibraries();
  testing::registerScaledStokesletKernel(libraries.kernels);
  return libraries;
}

// A level-1 sphere in free space with the given "Operator" settings, validated as a cell3d
// deck that knows the toy kernel.
Teuchos::RCP<Teuchos::ParameterList> toyDeck(const OperatorLibraries& libraries, bool wall,
                                             const std::vector<std::pair<std::string, std::string>>& operatorKeys)
{
  auto deck = scene::testing::sphereDeck(1, wall ? 2.0 : 0.0, wall);
  for (const auto& [key, value] : operatorKeys) {
    deck->sublist("Operator").set(key, value);
  }
  core::validateDeck(*deck, *validSceneRunParameters(*deck, "test", libraries), "test deck");
  return deck;
}

std::vector<double> velocityOfStretchedSphere(const OperatorLibraries& libraries, const Teuchos::ParameterList& deck,
                                              std::vector<double>& positions)
{
  scene::Scene scene(scene::describeScene(deck), deck, Tpetra::getDefaultComm(), kernelsForDeck(libraries, deck));
  positions = scene.initialPositions();
  for (std::size_t i = 0; i < positions.size(); i += 3) {
    positions[i] *= 1.2; // a loaded membrane: the single layer matters
  }
  std::vector<double> velocities;
  scene.velocity(0.0, positions, velocities);
  return velocities;
}

TEST(OperatorPlugins, ToyKernelFromTheDeckScalesTheStokeslet)
{
  const OperatorLibraries libraries = librariesWithToyKernel();
  auto toy = toyDeck(libraries, false, {{"Kernel", "ScaledFreeSpace"}});
  toy->sublist("Operator").sublist("ScaledFreeSpace").set("Stokeslet scale", 2.5);
  core::validateDeck(*toy, *validSceneRunParameters(*toy, "test", libraries), "test deck");
  {
    const scene::Scene scene(scene::describeScene(*toy), *toy, Tpetra::getDefaultComm(), libraries.kernels);
    EXPECT_EQ(scene.kernelKey(), "ScaledFreeSpace");
    EXPECT_EQ(scene.kernelName(), "free space, scaled Stokeslet");
    EXPECT_EQ(scene.kernelParameters().get<double>("Stokeslet scale"), 2.5);
  }
  std::vector<double> positions;
  const std::vector<double> scaled = velocityOfStretchedSphere(libraries, *toy, positions);
  const std::vector<double> freeSpace = velocityOfStretchedSphere(libraries, *toyDeck(libraries, false, {}), positions);
  ASSERT_EQ(scaled.size(), freeSpace.size());
  // u = u_inf + c (u_FreeSpace - u_inf), u_inf = (y, 0, 0), lambda = 1. The toy kernel
  // divides Ca by c where this multiplies the disturbance by c: the two differ by a few
  // roundings of numbers of order 1, so 1e-12 is far above round-off and far below the
  // disturbance (checked to be > 1e-2, so the comparison cannot pass by accident).
  double largestDisturbance = 0.0;
  for (std::size_t i = 0; i < scaled.size(); ++i) {
    const double background = i % 3 == 0 ? positions[i + 1] : 0.0;
    largestDisturbance = std::max(largestDisturbance, std::abs(freeSpace[i] - background));
    EXPECT_NEAR(scaled[i], background + 2.5 * (freeSpace[i] - background), 1e-12) << "component " << i;
  }
  EXPECT_GT(largestDisturbance, 1e-2);
}

TEST(OperatorPlugins, AutoFollowsTheWallAndExistingDecksKeepTheirKernel)
{
  const OperatorLibraries libraries = librariesWithToyKernel();
  for (const bool wall : {false, true}) {
    const auto deck = toyDeck(libraries, wall, {});
    EXPECT_EQ(deck->sublist("Operator").get<std::string>("Kernel"), "Auto");
    const scene::Scene scene(scene::describeScene(*deck), *deck, Tpetra::getDefaultComm(), libraries.kernels);
    EXPECT_EQ(scene.kernelKey(), wall ? "Wall" : "FreeSpace");
  }
  // The explicit names give the same kernels.
  const auto wall = toyDeck(libraries, true, {{"Kernel", "Wall"}});
  EXPECT_EQ(scene::Scene(scene::describeScene(*wall), *wall, Tpetra::getDefaultComm(), libraries.kernels).kernelName(),
            "plane wall 3D");
}

TEST(OperatorPlugins, KernelForTheOtherFluidIsAnErrorNamingBothKeys)
{
  const OperatorLibraries libraries = librariesWithToyKernel();
  const std::vector<std::pair<bool, std::string>> mismatches{
      {false, "Wall"}, {true, "FreeSpace"}, {true, "ScaledFreeSpace"}};
  for (const auto& [wall, kernel] : mismatches) {
    const auto deck = toyDeck(libraries, wall, {{"Kernel", kernel}});
    const std::string error = inputErrorMessage(
        [&] { scene::Scene(scene::describeScene(*deck), *deck, Tpetra::getDefaultComm(), libraries.kernels); });
    EXPECT_NE(error.find("'Operator/Kernel' = " + kernel), std::string::npos) << error;
    EXPECT_NE(error.find(std::string("'Wall/Enabled' = ") + (wall ? "true" : "false")), std::string::npos) << error;
  }
}

TEST(OperatorPlugins, UnknownNamesListTheRegisteredOnes)
{
  const OperatorLibraries libraries = librariesWithToyKernel();
  // The deck: the choices come from the registries.
  const std::string kernel = inputErrorMessage([&] { toyDeck(libraries, false, {{"Kernel", "ScaledFreeSpac"}}); });
  EXPECT_NE(kernel.find("one of: Auto, FreeSpace, Periodic, PeriodicChannel, PeriodicWall, ScaledFreeSpace, Wall"),
            std::string::npos)
      << kernel;
  EXPECT_NE(kernel.find("did you mean \"ScaledFreeSpace\""), std::string::npos) << kernel;
  const std::string summation = inputErrorMessage([&] { toyDeck(libraries, false, {{"Summation", "FMM"}}); });
  EXPECT_NE(summation.find("one of: Direct, Treecode"), std::string::npos) << summation;
  // A list no validator saw: the registry's own message.
  Teuchos::ParameterList operatorList;
  operatorList.set("Kernel", "Hasimoto");
  const std::string unvalidated = inputErrorMessage(
      [&] { operators::readKernelChoice(operatorList, libraries.kernels.infos(), domain::Domain::unbounded()); });
  EXPECT_NE(
      unvalidated.find("no Green's function kernel named 'Hasimoto'; registered: FreeSpace, Periodic, PeriodicChannel, "
                       "PeriodicWall, ScaledFreeSpace, Wall."),
      std::string::npos)
      << unvalidated;
}

// A far-field back-end that supports no kernel.
class NoKernelBackEnd final : public operators::FarFieldBackEnd {
public:
  std::string name() const override { return "NoKernels"; }
  std::unique_ptr<operators::FarFieldSummation> forKernel(std::type_index, const std::string&) const override
  {
    return nullptr;
  }
};

// A back-end without the kernel the deck names is refused when the scene is built, before
// the first step, naming both keys; with lambda != 1 the double layer's sums, which it would
// also have to do, never start.
TEST(OperatorPlugins, SummationWithoutTheKernelIsRefusedAtStartUpNamingBothKeys)
{
  OperatorLibraries libraries = librariesWithToyKernel();
  libraries.summations.add("NoKernels", "supports no kernel", [](const Teuchos::ParameterList&) {
    return std::shared_ptr<const operators::FarFieldBackEnd>(std::make_shared<NoKernelBackEnd>());
  });
  for (const bool wall : {false, true}) {
    auto deck = scene::testing::sphereDeck(1, wall ? 2.0 : 0.0, wall);
    deck->sublist("Flow").set("Viscosity ratio", 5.0);
    deck->sublist("Operator").set("Summation", "NoKernels");
    core::validateDeck(*deck, *validSceneRunParameters(*deck, "test", libraries), "test deck");
    const std::string error = inputErrorMessage([&] {
      scene::Scene(scene::describeScene(*deck), *deck, Tpetra::getDefaultComm(), kernelsForDeck(libraries, *deck));
    });
    EXPECT_NE(error.find("'Operator/Summation' = NoKernels does not support the"), std::string::npos) << error;
    EXPECT_NE(error.find("kernel ('Operator/Kernel')"), std::string::npos) << error;
  }
}

TEST(OperatorPlugins, KernelSublistIsValidated)
{
  const OperatorLibraries libraries = librariesWithToyKernel();
  auto deck = scene::testing::sphereDeck(1, 0.0, false);
  deck->sublist("Operator").set("Kernel", "ScaledFreeSpace");
  deck->sublist("Operator").sublist("ScaledFreeSpace").set("Stokeslet scal", 2.0);
  const std::string misspelt = inputErrorMessage(
      [&] { core::validateDeck(*deck, *validSceneRunParameters(*deck, "test", libraries), "test deck"); });
  EXPECT_NE(misspelt.find("Stokeslet scal"), std::string::npos) << misspelt;
  EXPECT_NE(misspelt.find("Operator/ScaledFreeSpace"), std::string::npos) << misspelt;

  deck->sublist("Operator").sublist("ScaledFreeSpace").remove("Stokeslet scal");
  deck->sublist("Operator").sublist("ScaledFreeSpace").set("Stokeslet scale", -1.0);
  const std::string negative = inputErrorMessage(
      [&] { core::validateDeck(*deck, *validSceneRunParameters(*deck, "test", libraries), "test deck"); });
  EXPECT_NE(negative.find("Stokeslet scale"), std::string::npos) << negative;
  // The standard libraries do not know the toy kernel, nor its sublist.
  EXPECT_NE(inputErrorMessage([&] { core::validateDeck(*deck, *validSceneRunParameters(*deck, "test"), "test deck"); }),
            "no InputError");
}

} // namespace
} // namespace capsula::run
