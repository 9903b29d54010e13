// A membrane law added from outside the elasticity package (HookeanMembraneLaw.hpp): one
// registration makes it a choice of 'Cells/Cell k/Membrane law' with its own key, the scene
// builds its membranes from it, its nodal forces are the gradient of its energy and an
// inflated sphere carries its closed-form tension; names and keys it does not know are
// refused naming the deck key. No list of law names is touched.
#include "HookeanMembraneLaw.hpp"
#include "SceneTestDecks.hpp"

#include "../elasticity/MembraneTesting.hpp"

#include <capsula/core/Deck.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/elasticity/MembraneLawChoice.hpp>
#include <capsula/elasticity/MembraneMechanics.hpp>
#include <capsula/mesh/Shapes.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace membrane_law_plugin_test { // the file's own names, apart from those of the files compiled with it
namespace {

namespace core = capsula::core;
namespace elasticity = capsula::elasticity;
namespace scene = capsula::scene;
using capsula::mesh::SurfaceMesh;
using capsula::mesh::Vec3;
using scene::testing::HookeanMembraneLaw;

constexpr double G = 0.7;
constexpr double nu = 0.3;

elasticity::MembraneLawRegistry lawsWithHookean()
{
  auto laws = elasticity::builtInMembraneLaws();
  scene::testing::registerHookeanMembraneLaw(laws);
  return laws;
}

// A level-1 sphere whose Cell 0 has `law`, 'Shear modulus' 0.5 and, unless nu is NaN,
// 'Poisson ratio' = nu; validated against the keys `laws` declare.
Teuchos::RCP<Teuchos::ParameterList> deckWithLaw(const elasticity::MembraneLawRegistry& laws, const std::string& law,
                                                 double poissonRatio)
{
  auto deck = scene::testing::sphereDeck(1, 2.0, true);
  auto& cell = deck->sublist("Cells").sublist("Cell 0");
  cell.set("Membrane law", law);
  cell.set("Shear modulus", 0.5);
  if (!std::isnan(poissonRatio)) {
    cell.set(HookeanMembraneLaw::poissonRatioKey, poissonRatio);
  }
  auto valid = Teuchos::rcp(new Teuchos::ParameterList("test"));
  scene::declareSceneParameters(*valid, *deck, 1, laws);
  capsula::operators::declareOperatorParameters(*valid);
  scene::declareStiffSolverParameters(core::declareSublist(valid->sublist("Solver"), "Stiff", "The stiff solves."));
  scene::declareMeshEvolutionParameters(*valid);
  core::validateDeck(*deck, *valid, "test deck");
  return deck;
}

std::string inputError(const std::function<void()>& build)
{
  try {
    build();
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

} // namespace

TEST(MembraneLawPlugin, TheDeckChoosesTheRegisteredLawWithItsKey)
{
  const auto laws = lawsWithHookean();
  EXPECT_EQ(laws.names(), (std::vector<std::string>{"Hookean", "NeoHookean", "Skalak"}));
  const auto deck = deckWithLaw(laws, "Hookean", nu);
  const auto description = scene::describeScene(*deck, laws);
  const scene::CellDescription& cell = description.cells[0];
  EXPECT_EQ(cell.membraneLaw, "Hookean");
  EXPECT_EQ(cell.membraneLawParameters.get<double>(HookeanMembraneLaw::poissonRatioKey), nu);
  ASSERT_NE(cell.law, nullptr);
  // The law built is the plug-in with the cell's G = 0.5 and the deck's nu: its energy at
  // one state against the closed form (the same arithmetic up to its order: 1e-15).
  const double I1 = 0.3, I2 = 0.2;
  const double expected = 0.5 / (4.0 * (1.0 - nu)) * (I1 * I1 + 2.0 * (1.0 - nu) * (I1 - I2));
  EXPECT_NEAR(cell.law->energyDensity(I1, I2), expected, 1e-15);
  EXPECT_EQ(cell.law->shearModulus(), 0.5);

  // The scene's membrane is that law, and its summary line names the law's key.
  static const auto kernels = capsula::operators::builtInKernels();
  const scene::Scene built(description, *deck, Tpetra::getDefaultComm(), kernels);
  EXPECT_EQ(built.membrane(0).law().name(), "Hookean");
  EXPECT_TRUE(std::any_of(built.terms().begin(), built.terms().end(), [](const std::string& line) {
    return contains(line, "Cells/Cell 0: Hookean (Poisson ratio = 0.3)");
  }));

  // Left out, the key takes its declared default; a Skalak cell's deck carries it too
  // (every law's keys are declared), and Skalak keeps its own key's default.
  const auto defaults = deckWithLaw(laws, "Skalak", std::nan(""));
  EXPECT_EQ(defaults->sublist("Cells").sublist("Cell 0").get<double>(HookeanMembraneLaw::poissonRatioKey), 0.5);
  const auto skalak = scene::describeScene(*defaults, laws);
  EXPECT_EQ(skalak.cells[0].membraneLaw, "Skalak");
  EXPECT_EQ(skalak.cells[0].membraneLawParameters.get<double>("Area dilation C"), 2.5);
  EXPECT_FALSE(skalak.cells[0].membraneLawParameters.isParameter(HookeanMembraneLaw::poissonRatioKey));
}

TEST(MembraneLawPlugin, UnknownNamesAndBadKeysAreRefusedNamingTheKey)
{
  const auto laws = lawsWithHookean();
  // Validation: the choices come from the registry, with the closest one.
  const std::string misspelt = inputError([&] { deckWithLaw(laws, "Hokean", nu); });
  EXPECT_TRUE(contains(misspelt, "'Cells/Cell 0/Membrane law'")) << misspelt;
  EXPECT_TRUE(contains(misspelt, "Hookean, NeoHookean, Skalak")) << misspelt;
  EXPECT_TRUE(contains(misspelt, "did you mean \"Hookean\"")) << misspelt;
  // Without the plug-in, "Hookean" is no choice.
  const std::string builtInOnly =
      inputError([&] { deckWithLaw(elasticity::builtInMembraneLaws(), "Hookean", std::nan("")); });
  EXPECT_TRUE(contains(builtInOnly, "'Cells/Cell 0/Membrane law'")) << builtInOnly;
  EXPECT_TRUE(contains(builtInOnly, "did you mean \"NeoHookean\"")) << builtInOnly;
  // The law's own validator, with the key's full path.
  const std::string badRatio = inputError([&] { deckWithLaw(laws, "Hookean", 1.0); });
  EXPECT_TRUE(contains(badRatio, "'Cells/Cell 0/Poisson ratio'")) << badRatio;

  // Reading a deck the registry cannot serve (validated against another registry).
  const auto deck = deckWithLaw(laws, "Hookean", nu);
  const std::string unread = inputError([&] { scene::describeScene(*deck, elasticity::builtInMembraneLaws()); });
  EXPECT_TRUE(contains(unread, "'Cells/Cell 0/Membrane law'")) << unread;
  EXPECT_TRUE(contains(unread, "There is no membrane law named 'Hookean'")) << unread;
  EXPECT_TRUE(contains(unread, "Did you mean 'NeoHookean'?")) << unread;

  // Registration: a taken name, and a key that would replace a key of the cell.
  auto again = lawsWithHookean();
  EXPECT_TRUE(contains(inputError([&] { scene::testing::registerHookeanMembraneLaw(again); }),
                       "'Hookean' is registered already"));
  auto clashing = elasticity::builtInMembraneLaws();
  auto keys = Teuchos::rcp(new Teuchos::ParameterList("Clash"));
  core::declareReal(*keys, "Prestress", 0.0, "clashes with the cell's key");
  clashing.add("Clash", {"a law whose key is the cell's", keys}, [](double modulus, const Teuchos::ParameterList&) {
    return std::make_unique<HookeanMembraneLaw>(modulus, 0.0);
  });
  Teuchos::ParameterList cell;
  const std::string clash = inputError([&] { scene::declareCellParameters(cell, {0.0, 2.0, 0.0}, clashing); });
  EXPECT_TRUE(contains(clash, "'Prestress' of the membrane law 'Clash'")) << clash;
  // A key the law does not declare, handed to the factory directly.
  Teuchos::ParameterList foreign;
  foreign.set("Area dilation C", 2.5);
  EXPECT_TRUE(contains(inputError([&] { laws.create("Hookean", G, foreign); }), "has no key 'Area dilation C'"));
}

TEST(MembraneLawPlugin, NodalForcesAreTheGradientOfItsEnergy)
{
  Teuchos::ParameterList keys;
  keys.set(HookeanMembraneLaw::poissonRatioKey, nu);
  const std::shared_ptr<const elasticity::MembraneLaw> law = lawsWithHookean().create("Hookean", G, keys);
  const SurfaceMesh mesh = capsula::mesh::makeSphere(1, 1.0);
  const std::vector<double> x = elasticity::testing::mapNodes(mesh.positions(), elasticity::testing::smoothDeformation);
  elasticity::MembraneDiscretisation virtualWork;
  virtualWork.forceMethod = elasticity::MembraneForceMethod::VirtualWork;
  elasticity::MembraneMechanics m(mesh, mesh.positions(), law, virtualWork);
  m.evaluate(x.data());
  double scale = 0.0, worst = 0.0;
  for (const Vec3& F : m.nodalForces()) {
    scale = std::max(scale, F.norm());
  }
  // Central differences of the strain energy (the same rule and material coordinates):
  // truncation ~h^2 E''' ~ 1e-10 relative, round-off ~eps E / h ~ 1e-10; a wrong factor
  // or sign in energyDerivatives moves the forces by O(scale).
  const double h = 1e-5;
  for (int node = 0; node < mesh.numNodes(); node += 5) {
    for (int d = 0; d < 3; ++d) {
      std::vector<double> plus = x, minus = x;
      plus[3 * node + d] += h;
      minus[3 * node + d] -= h;
      const double slope = (m.strainEnergy(plus.data()) - m.strainEnergy(minus.data())) / (2.0 * h);
      worst = std::max(worst, std::abs(slope - m.nodalForces()[node][d]));
    }
  }
  EXPECT_GT(scale, 0.1 * G); // the deformation loads the membrane
  EXPECT_LT(worst, 1e-8 * scale);
}

TEST(MembraneLawPlugin, InflatedSphereCarriesTheClosedFormTension)
{
  // A uniform dilation s: w(s) = G / (4 (1 - nu)) (I1^2 + 2 (1 - nu)(I1 - I2)) with
  // I1 = 2 (s^2 - 1), I2 = s^4 - 1, and T = (1/s) dw/dlambda1 = G (1 + nu) / (1 - nu) (s^2 - 1):
  // the small-strain area modulus G (1 + nu) / (1 - nu) times the area strain, which
  // Laplace's law balances with the pressure 2 T / R.
  Teuchos::ParameterList keys;
  keys.set(HookeanMembraneLaw::poissonRatioKey, nu);
  const std::shared_ptr<const elasticity::MembraneLaw> law = lawsWithHookean().create("Hookean", G, keys);
  const SurfaceMesh mesh = capsula::mesh::makeSphere(2, 1.3);
  for (double s : {0.9, 1.05, 1.3}) {
    const auto current = elasticity::testing::mapNodes(mesh.positions(), [s](const Vec3& X) { return s * X; });
    elasticity::MembraneMechanics m(mesh, mesh.positions(), law);
    m.evaluate(current.data());
    const double tension = G * (1.0 + nu) / (1.0 - nu) * (s * s - 1.0);
    for (const auto& principal : m.nodalPrincipalTensions()) {
      // Exact for the discrete mesh (every element's A is s (I - N N)): round-off of the
      // O(1) kinematics times G.
      EXPECT_NEAR(principal.major, tension, 1e-10 * G) << "s " << s;
      EXPECT_NEAR(principal.minor, tension, 1e-10 * G) << "s " << s;
    }
  }
}

} // namespace membrane_law_plugin_test
