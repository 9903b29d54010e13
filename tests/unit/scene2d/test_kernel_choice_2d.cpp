// 'Operator/Kernel' in the 2D model: Auto follows Wall/Enabled, the names come from the
// KernelRegistry2D, a kernel for the other fluid domain is refused naming both keys, and a
// registered kernel's own sublist reaches its factory.
#include "Tether2DTesting.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/testing/InputErrorMessage.hpp>
#include <capsula/core/ParameterDeclaration.hpp>
#include <capsula/scene2d/KernelRegistry2D.hpp>
#include <capsula/operators/OperatorParameters.hpp>
#include <capsula/scene2d/CapsuleModel2D.hpp>
#include <capsula/scene2d/CellContour2D.hpp>
#include <capsula/scene2d/FlowModel2D.hpp>

#include <Teuchos_DefaultSerialComm.hpp>
#include <gtest/gtest.h>

#include <memory>
#include <functional>
#include <string>

namespace capsula::scene2d {
namespace {

using capsula::testing::inputErrorMessage;

CapsuleModel2D modelOf(const Teuchos::ParameterList& deck, const scene2d::KernelRegistry2D& kernels)
{
  return CapsuleModel2D(
      Teuchos::rcp(new Teuchos::SerialComm<int>), readCellSettings2D(deck.sublist("Cell")),
      readFlowSettings2D(deck.sublist("Flow"), deck.sublist("Wall"), deck.sublist("Operator"), kernels),
      scene2d::readContourDiscretisation2D(deck.sublist("Discretisation")),
      operators::readSolverParameters(deck.sublist("Solver")), kernels);
}

TEST(KernelChoice2D, AutoFollowsTheWall)
{
  const auto kernels = scene2d::builtInKernels2D();
  EXPECT_EQ(modelOf(testing::modelDeck2D({"Cell/Number of points=32"}), kernels).kernelName(), "plane wall 2D");
  EXPECT_EQ(modelOf(testing::modelDeck2D({"Cell/Number of points=32", "Wall/Enabled=false"}), kernels).kernelName(),
            "free-space 2D");
  EXPECT_EQ(
      modelOf(testing::modelDeck2D({"Cell/Number of points=32", "Operator/Kernel=FreeSpace", "Wall/Enabled=false"}),
              kernels)
          .kernelName(),
      "free-space 2D");
}

TEST(KernelChoice2D, KernelForTheOtherFluidOrUnknownIsAnError)
{
  const auto noWall = testing::modelDeck2D({"Wall/Enabled=false", "Operator/Kernel=Wall"});
  const std::string wallError = inputErrorMessage(
      [&] { readFlowSettings2D(noWall.sublist("Flow"), noWall.sublist("Wall"), noWall.sublist("Operator")); });
  EXPECT_NE(wallError.find("'Operator/Kernel' = Wall"), std::string::npos) << wallError;
  EXPECT_NE(wallError.find("'Wall/Enabled' = false"), std::string::npos) << wallError;
  const auto wall = testing::modelDeck2D({"Operator/Kernel=FreeSpace"});
  const std::string freeError = inputErrorMessage(
      [&] { readFlowSettings2D(wall.sublist("Flow"), wall.sublist("Wall"), wall.sublist("Operator")); });
  EXPECT_NE(freeError.find("'Wall/Enabled' = true"), std::string::npos) << freeError;
  const std::string unknown = inputErrorMessage([] { testing::modelDeck2D({"Operator/Kernel=Periodic"}); });
  EXPECT_NE(unknown.find("one of: Auto, FreeSpace, Wall"), std::string::npos) << unknown;
}

TEST(KernelChoice2D, RegisteredKernelGetsItsSublist)
{
  // A kernel with a setting of its own; the factory records what it was given.
  auto received = std::make_shared<std::string>();
  auto keys = Teuchos::rcp(new Teuchos::ParameterList("Labelled"));
  core::declareString(*keys, "Label", "none", "Recorded by the factory.");
  auto kernels = scene2d::builtInKernels2D();
  kernels.add("Labelled", operators::KernelInfo{"Free space, labelled.", operators::FluidDomain::Unbounded, keys},
              [received](const Teuchos::RCP<const Teuchos::Comm<int>>& comm, int numNodes,
                         const scene2d::ContourDiscretisation2D& discretisation,
                         const operators::SolverParameters& solver, const Teuchos::ParameterList& settings) {
                *received = settings.get<std::string>("Label");
                return scene2d::makeInterfaceVelocity2D(false, comm, numNodes, discretisation, solver);
              });
  Teuchos::ParameterList valid("tether2d");
  declareModelParameters2D(valid, kernels);
  const auto labelled = testing::deckWith(valid, {"Cell/Number of points=32", "Wall/Enabled=false",
                                                  "Operator/Kernel=Labelled", "Operator/Labelled/Label=toy"});
  const CapsuleModel2D model = modelOf(labelled, kernels);
  EXPECT_EQ(*received, "toy");
  EXPECT_EQ(model.flow().kernel.name, "Labelled");
  const std::string misspelt = inputErrorMessage([&] { testing::deckWith(valid, {"Operator/Labelled/Lable=toy"}); });
  EXPECT_NE(misspelt.find("Lable"), std::string::npos) << misspelt;
}

} // namespace
} // namespace capsula::scene2d
