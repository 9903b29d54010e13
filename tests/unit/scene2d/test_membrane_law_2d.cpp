// 'Cell/Membrane law' in the 2D model: the names come from a MembraneLawRegistry2D, the
// default is the thesis's Hookean law, and a law registered here (a strain-stiffening one
// with a key of its own) reaches the model's membrane with its key, touching no list of
// names; an unknown name is refused naming the key.
#include "Tether2DTesting.hpp"

#include <capsula/contour/Contour.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>
#include <capsula/scene2d/ElasticMembrane2D.hpp>
#include <capsula/scene2d/MembraneLawRegistry2D.hpp>
#include <capsula/scene2d/KernelRegistry2D.hpp>
#include <capsula/operators/OperatorParameters.hpp>
#include <capsula/scene2d/CapsuleModel2D.hpp>
#include <capsula/scene2d/CellContour2D.hpp>
#include <capsula/scene2d/FlowModel2D.hpp>
#include <capsula/testing/InputErrorMessage.hpp>

#include <Teuchos_DefaultSerialComm.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

// The file's own names, apart from those of the files compiled with it.
namespace capsula::scene2d::membrane_law_2d_test {
namespace {

using capsula::testing::inputErrorMessage;

/// gamma = E ((omega - 1) + k (omega - 1)^3), w = E ((omega - 1)^2 / 2 + k (omega - 1)^4 / 4):
/// a membrane that stiffens in stretch, k its 'Cubic stiffness'.
class StiffeningLaw2D final : public scene2d::MembraneLaw2D {
public:
  StiffeningLaw2D(double modulus, double cubic) : modulus_(modulus), cubic_(cubic) {}
  std::string name() const override { return "Stiffening"; }
  double tension(double stretch) const override
  {
    const double strain = stretch - 1.0;
    return modulus_ * (strain + cubic_ * strain * strain * strain);
  }
  double energyDensity(double stretch) const override
  {
    const double strain2 = (stretch - 1.0) * (stretch - 1.0);
    return modulus_ * (0.5 * strain2 + 0.25 * cubic_ * strain2 * strain2);
  }

private:
  double modulus_;
  double cubic_;
};

scene2d::MembraneLawRegistry2D lawsWithStiffening()
{
  auto laws = scene2d::builtInMembraneLaws2D();
  auto keys = Teuchos::rcp(new Teuchos::ParameterList("Stiffening"));
  core::declareReal(*keys, "Cubic stiffness", 1.0, "k of the stiffening law.", core::atLeast(0.0));
  laws.add("Stiffening", {"tension E ((omega - 1) + k (omega - 1)^3).", keys},
           [](double modulus, const Teuchos::ParameterList& settings) {
             return std::make_unique<StiffeningLaw2D>(modulus, settings.get<double>("Cubic stiffness"));
           });
  return laws;
}

Teuchos::ParameterList deckOf(const scene2d::MembraneLawRegistry2D& laws, const std::vector<std::string>& overrides)
{
  Teuchos::ParameterList valid("tether2d");
  declareModelParameters2D(valid, scene2d::builtInKernels2D(), laws);
  return testing::deckWith(valid, overrides);
}

CapsuleModel2D modelOf(const Teuchos::ParameterList& deck, const scene2d::MembraneLawRegistry2D& laws)
{
  return CapsuleModel2D(Teuchos::rcp(new Teuchos::SerialComm<int>), readCellSettings2D(deck.sublist("Cell"), laws),
                        readFlowSettings2D(deck.sublist("Flow"), deck.sublist("Wall")),
                        scene2d::readContourDiscretisation2D(deck.sublist("Discretisation")),
                        operators::readSolverParameters(deck.sublist("Solver")));
}

// The largest |gamma_i - expected(omega_i)| of the model's membrane on its initial state,
// an ellipse stretched by 1 + alpha over its reference (Cell/Prestress), and the smallest
// stretch there.
double worstTension(const CapsuleModel2D& model, const scene2d::MembraneLaw2D& expected, double& leastStretch)
{
  const auto state = model.membrane(model.contour(model.initialState()));
  double worst = 0.0;
  leastStretch = state.stretch().minCoeff();
  for (Eigen::Index i = 0; i < state.tension().size(); ++i) {
    worst = std::max(worst, std::abs(state.tension()(i) - expected.tension(state.stretch()(i))));
  }
  return worst;
}

TEST(MembraneLaw2D, TheDefaultIsTheThesisHookeanLaw)
{
  const auto deck = testing::modelDeck2D({"Cell/Number of points=32"});
  EXPECT_EQ(deck.sublist("Cell").get<std::string>("Membrane law"), "Hookean");
  const CellSettings2D cell = readCellSettings2D(deck.sublist("Cell"));
  EXPECT_EQ(cell.membraneLaw->name(), "Hookean");
  // E = 1: gamma(1.1) = 0.1 (eq A.36), to round-off.
  EXPECT_NEAR(cell.membraneLaw->tension(1.1), 0.1, 1e-15);
  EXPECT_EQ(CellSettings2D().membraneLaw->name(), "Hookean");
}

TEST(MembraneLaw2D, ARegisteredLawReachesTheModelWithItsKey)
{
  const auto laws = lawsWithStiffening();
  const auto deck = deckOf(laws, {"Cell/Number of points=32", "Cell/Prestress=0.2", "Cell/Membrane law=Stiffening",
                                  "Cell/Cubic stiffness=4"});
  const CapsuleModel2D model = modelOf(deck, laws);
  const StiffeningLaw2D expected(1.0, 4.0);
  double leastStretch = 0.0;
  // The membrane's tensions are the law's at its stretches (the spline's knot values of the
  // same numbers: round-off of O(1) tensions).
  EXPECT_LT(worstTension(model, expected, leastStretch), 1e-12);
  // The prestress stretches every marker by ~1.2, where the cubic term adds 4 * 0.2^3 = 0.032
  // to the Hookean 0.2: the comparison would see a wrong law or key.
  EXPECT_GT(leastStretch, 1.1);
  EXPECT_GT(std::abs(expected.tension(leastStretch) - (leastStretch - 1.0)), 4 * 0.1 * 0.1 * 0.1 * 0.9);

  // The energy density's derivative is the tension (central differences: truncation
  // h^2 w''' / 6 ~ 1e-12, round-off eps / h ~ 1e-10).
  for (double omega : {0.8, 1.0, 1.3}) {
    const double h = 1e-6;
    const double slope = (expected.energyDensity(omega + h) - expected.energyDensity(omega - h)) / (2.0 * h);
    EXPECT_NEAR(slope, expected.tension(omega), 1e-9) << omega;
  }
}

TEST(MembraneLaw2D, UnknownNameIsRefusedNamingTheKey)
{
  const std::string misspelt = inputErrorMessage([] { testing::modelDeck2D({"Cell/Membrane law=Hooke"}); });
  EXPECT_NE(misspelt.find("'Cell/Membrane law'"), std::string::npos) << misspelt;
  EXPECT_NE(misspelt.find("did you mean \"Hookean\""), std::string::npos) << misspelt;
  // A deck validated with the plug-in but read without it.
  const auto laws = lawsWithStiffening();
  const auto deck = deckOf(laws, {"Cell/Membrane law=Stiffening"});
  const std::string unread = inputErrorMessage([&] { readCellSettings2D(deck.sublist("Cell")); });
  EXPECT_NE(unread.find("'Cell/Membrane law'"), std::string::npos) << unread;
  EXPECT_NE(unread.find("There is no membrane law named 'Stiffening'; registered: Hookean."), std::string::npos)
      << unread;
}

} // namespace
} // namespace capsula::scene2d::membrane_law_2d_test
