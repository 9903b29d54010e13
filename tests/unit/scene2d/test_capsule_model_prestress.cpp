// Cell/Prestress in the 2D cell model: the state starts at the deck's ellipse, the membrane's
// reference is that ellipse shrunk by 1 + alpha (elasticity/Prestress.hpp), and A/A0 and the
// area drift are measured against the initial contour, not the smaller reference.
#include "Tether2DTesting.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/operators/OperatorParameters.hpp>
#include <capsula/scene2d/CapsuleModel2D.hpp>
#include <capsula/scene2d/CellMetrics2D.hpp>

#include <Teuchos_DefaultSerialComm.hpp>
#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace capsula;
using namespace capsula::scene2d;
using capsula::scene2d::testing::modelDeck2D;

namespace {

CapsuleModel2D modelOf(const Teuchos::ParameterList& deck)
{
  return CapsuleModel2D(Teuchos::rcp(new Teuchos::SerialComm<int>), readCellSettings2D(deck.sublist("Cell")),
                        readFlowSettings2D(deck.sublist("Flow"), deck.sublist("Wall")),
                        scene2d::readContourDiscretisation2D(deck.sublist("Discretisation")),
                        operators::readSolverParameters(deck.sublist("Solver")));
}

} // namespace

TEST(CapsuleModel2DPrestress, InitialContourIsTheDeckShapeUnderUniformTension)
{
  const double alpha = 0.2;
  const CapsuleModel2D plain = modelOf(modelDeck2D({"Cell/Number of points=64", "Cell/Aspect ratio=0.5"}));
  const CapsuleModel2D model =
      modelOf(modelDeck2D({"Cell/Number of points=64", "Cell/Aspect ratio=0.5", "Cell/Prestress=0.2"}));
  // The same initial state as without prestress (bit for bit: the state is the deck's ellipse).
  EXPECT_EQ(model.initialState(), plain.initialState());
  const contour::Contour initial = model.contour(model.initialState());
  const scene2d::MembraneState2D membrane = model.membrane(initial);
  // Tension E (omega - 1) with E = 1 (loads in E/L) and omega = 1 + alpha at every node: the
  // reference is a similar contour, so to round-off (1e-12 leaves room for the spline solves).
  EXPECT_LT((membrane.tension().array() - alpha).abs().maxCoeff(), 1e-12);
  EXPECT_LT(plain.membrane(initial).tension().cwiseAbs().maxCoeff(), 1e-12);
  // A/A0 = 1 and no area drift at t = 0: A0 and the area are the initial contour's. Against the
  // shrunk reference they would be 1.2 and 0.44.
  const std::vector<double> atRest(2 * static_cast<std::size_t>(model.numberOfNodes()), 0.0);
  const CellMetrics2D m = cellMetrics2D(model, initial, membrane, atRest);
  EXPECT_NEAR(m.contourLengthRatio, 1.0, 1e-14);
  EXPECT_NEAR(m.areaDrift, 0.0, 1e-14);
  // The uniform tension on a closed contour has no net force (int gamma kappa n dl = 0).
  EXPECT_LT(m.tetherForce, 1e-10);
}

TEST(CapsuleModel2DPrestress, DeckRejectsANegativePrestressByName)
{
  try {
    modelDeck2D({"Cell/Prestress=-0.1"});
    FAIL() << "a negative prestress was accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("Prestress"), std::string::npos) << e.what();
  }
}
