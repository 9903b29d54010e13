// The Krylov method of the viscosity-ratio equation, chosen by its Belos name
// ('Solver/Method', KrylovMethod.hpp), and the parameters of 'Solver/Belos' handed to it:
// every method offered reaches the velocity of the default Block GMRES, the solve is the
// method's (its Belos timer runs), the sublist's entries win over Capsula's, and unknown
// names and keys are refused at start-up, named.
#include "OperatorTesting.hpp"

#include <capsula/core/Deck.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/operators/KrylovMethod.hpp>
#include <capsula/testing/InputErrorMessage.hpp>

#include <Teuchos_TimeMonitor.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace {

using namespace capsula;
using namespace capsula::operators;
using capsula::testing::inputErrorMessage;
using mesh::Vec3;

// A sphere of radius 0.8 whose lowest point is 0.4 above the wall, in shear, loaded with the
// translating drop's traction (test_velocity.cpp): the lambda = 5 system of a cell near the wall.
struct LambdaFiveSystem {
  std::unique_ptr<BoundaryIntegralSolver> solver;
  std::vector<double> elementLoads;
  FlowConditions flow;

  VelocitySolution solve() const
  {
    return solver->nodeVelocities(LoadDensity::constantOverElements(elementLoads), flow);
  }
};

LambdaFiveSystem lambdaFiveSystem(const SolverParameters& parameters)
{
  mesh::Placement placement;
  placement.centre = Vec3(0.3, 1.2, 0.1);
  LambdaFiveSystem system;
  system.solver = operators::testing::makeSolver("Wall", mesh::makeSphere(2, 0.8, placement), 5.0, {}, parameters);
  const Vec3 U(0.6, -0.3, 0.8);
  system.elementLoads = operators::testing::elementAverages(system.solver->surfaces(), [&](const Vec3& x, const Vec3&) {
    const Vec3 n = (x - placement.centre).normalized();
    return Vec3(-3.0 * (2.0 + 3.0 * 5.0) / (2.0 * 0.8 * 6.0) * U.dot(n) * n);
  });
  system.flow.capillaryNumber = 0.4;
  return system;
}

// Belos names its timer after the solver manager's class.
const std::map<std::string, std::string> kSolverClass{{"Block GMRES", "BlockGmresSolMgr"},
                                                      {"Pseudo Block GMRES", "PseudoBlockGmresSolMgr"},
                                                      {"GCRODR", "GCRODRSolMgr"},
                                                      {"TFQMR", "TFQMRSolMgr"},
                                                      {"BiCGStab", "BiCGStabSolMgr"}};

int solvesBy(const std::string& method)
{
  const auto timer = Teuchos::TimeMonitor::lookupCounter("Belos: " + kSolverClass.at(method) + " total solve time");
  return timer.is_null() ? 0 : timer->numCalls();
}

Teuchos::ParameterList validatedSolverList(const std::string& method, const Teuchos::ParameterList& belos)
{
  Teuchos::ParameterList valid("deck");
  declareOperatorParameters(valid);
  Teuchos::ParameterList deck("deck");
  deck.sublist("Solver").set("Method", method);
  deck.sublist("Solver").sublist("Belos").setParameters(belos);
  core::validateDeck(deck, valid, "deck.xml");
  return deck.sublist("Solver");
}

bool mentions(const std::string& text, const std::string& piece)
{
  return text.find(piece) != std::string::npos;
}

TEST(KrylovMethod, OfferedMethodsAreBelosSolversForANonsymmetricOperator)
{
  EXPECT_EQ(krylovMethods(),
            (std::vector<std::string>{"Block GMRES", "Pseudo Block GMRES", "GCRODR", "TFQMR", "BiCGStab"}));
  EXPECT_EQ(krylovMethods().front(), SolverParameters{}.method);
  for (const std::string& method : krylovMethods()) {
    const auto valid = belosValidParameters(method);
    EXPECT_TRUE(valid->isParameter("Convergence Tolerance")) << method;
    EXPECT_TRUE(valid->isParameter("Maximum Iterations")) << method;
  }
}

TEST(KrylovMethod, EachMethodReachesTheBlockGmresVelocityAtLambdaFive)
{
  const auto reference = lambdaFiveSystem({});
  const VelocitySolution gmres = reference.solve();
  double scale = 0.0;
  for (const double u : gmres.velocities) {
    scale = std::max(scale, std::abs(u));
  }
  for (const std::string& method : krylovMethods()) {
    SolverParameters parameters;
    parameters.method = method;
    const auto system = lambdaFiveSystem(parameters);
    const int before = solvesBy(method);
    const VelocitySolution solution = system.solve();
    EXPECT_EQ(solvesBy(method), before + 1) << method << " did not solve";
    EXPECT_GT(solution.iterations, 0) << method;
    EXPECT_LE(solution.residual, parameters.tolerance) << method;
    double difference = 0.0;
    for (std::size_t k = 0; k < gmres.velocities.size(); ++k) {
      difference = std::max(difference, std::abs(solution.velocities[k] - gmres.velocities[k]));
    }
    std::printf("%-20s %3d iterations, residual %.2e, max |u - u_BlockGMRES| / max |u| = %.2e\n", method.c_str(),
                solution.iterations, solution.residual, difference / scale);
    // Both solve to the relative residual 1e-10 and the equation is well conditioned (a
    // solution errs by at most ~4x the tolerance times max |u|, test_velocity.cpp), so any
    // two agree to 1e-9 of the largest velocity; a wrong solve misses by far more.
    EXPECT_LT(difference, 1e-9 * scale) << method;
  }
}

TEST(KrylovMethod, BelosSettingsTranslateTheKeysAndTheSublistWins)
{
  SolverParameters parameters;
  parameters.tolerance = 1e-7;
  parameters.restart = 20;
  parameters.maximumIterations = 90;
  const auto block = belosSettings(parameters, "Block GMRES", {});
  EXPECT_EQ(block->get<double>("Convergence Tolerance"), 1e-7);
  EXPECT_EQ(block->get<int>("Num Blocks"), 20);
  EXPECT_EQ(block->get<int>("Maximum Iterations"), 90);
  EXPECT_EQ(block->get<int>("Maximum Restarts"), 5); // 90 / 20 + 1: the iteration cap binds
  EXPECT_EQ(block->get<std::string>("Implicit Residual Scaling"), "Norm of RHS");
  EXPECT_EQ(block->get<std::string>("Explicit Residual Scaling"), "Norm of RHS");
  EXPECT_FALSE(block->isParameter("Explicit Residual Test")); // its own test confirms already
  // Only the parameters a method has; TFQMR is asked to confirm its estimate.
  const auto tfqmr = belosSettings(parameters, "TFQMR", {});
  EXPECT_FALSE(tfqmr->isParameter("Num Blocks"));
  EXPECT_FALSE(tfqmr->isParameter("Maximum Restarts"));
  EXPECT_TRUE(tfqmr->get<bool>("Explicit Residual Test"));
  EXPECT_EQ(tfqmr->get<std::string>("Explicit Residual Scaling"), "Norm of RHS");
  const auto bicgstab = belosSettings(parameters, "BiCGStab", {});
  EXPECT_EQ(bicgstab->get<std::string>("Implicit Residual Scaling"), "Norm of RHS");
  EXPECT_FALSE(bicgstab->isParameter("Explicit Residual Scaling"));
  // The sublist's entries replace Capsula's; the restarts follow the final restart length.
  Teuchos::ParameterList overrides;
  overrides.set("Num Blocks", 30);
  overrides.set("Convergence Tolerance", 1e-5);
  overrides.set("Orthogonalization", "DGKS");
  const auto replaced = belosSettings(parameters, "Block GMRES", overrides);
  EXPECT_EQ(replaced->get<int>("Num Blocks"), 30);
  EXPECT_EQ(replaced->get<int>("Maximum Restarts"), 4);
  EXPECT_EQ(replaced->get<double>("Convergence Tolerance"), 1e-5);
  EXPECT_EQ(replaced->get<std::string>("Orthogonalization"), "DGKS");
  Teuchos::ParameterList restarts;
  restarts.set("Maximum Restarts", 2);
  EXPECT_EQ(belosSettings(parameters, "Block GMRES", restarts)->get<int>("Maximum Restarts"), 2);
}

TEST(KrylovMethod, BelosSublistEntryLimitsTheSolveAndTheErrorNamesIt)
{
  for (const std::string& method : {std::string("Block GMRES"), std::string("TFQMR")}) {
    SolverParameters parameters;
    parameters.method = method;
    parameters.belos.set("Maximum Iterations", 1);
    const auto system = lambdaFiveSystem(parameters);
    try {
      system.solve();
      FAIL() << method << " converged in one iteration";
    } catch (const core::NumericalError& e) {
      const std::string text = e.what();
      EXPECT_TRUE(mentions(text, "'Solver/Method' = " + method + " for the viscosity-ratio equation stopped after"))
          << text;
      EXPECT_TRUE(mentions(text, "The entries of 'Solver/Belos' ('Maximum Iterations') take precedence")) << text;
    }
  }
}

TEST(KrylovMethod, UnknownMethodListsTheOfferedOnes)
{
  const std::string misspelt = inputErrorMessage([] { validatedSolverList("TFQMRR", {}); });
  EXPECT_TRUE(mentions(misspelt, "'Solver/Method'")) << misspelt;
  EXPECT_TRUE(mentions(misspelt, "one of: Block GMRES, Pseudo Block GMRES, GCRODR, TFQMR, BiCGStab")) << misspelt;
  EXPECT_TRUE(mentions(misspelt, "did you mean \"TFQMR\"")) << misspelt;
  // A list no validator saw: Belos's names for the same solvers are not taken either.
  SolverParameters flexible;
  flexible.method = "Flexible GMRES";
  const std::string unvalidated = inputErrorMessage([&] { validate(flexible); });
  EXPECT_TRUE(mentions(unvalidated, "'Solver/Method' = 'Flexible GMRES' is not offered; use one of Block GMRES, "
                                    "Pseudo Block GMRES, GCRODR, TFQMR, BiCGStab."))
      << unvalidated;
}

TEST(KrylovMethod, UnknownBelosKeyIsRefusedNamingIt)
{
  Teuchos::ParameterList misspelt;
  misspelt.set("Maximum Iteration", 5);
  const auto deck = validatedSolverList("Block GMRES", misspelt); // the deck check lets it through
  const std::string unknown = inputErrorMessage([&] { readSolverParameters(deck); });
  EXPECT_TRUE(mentions(unknown, "'Solver/Belos/Maximum Iteration' is not a parameter of the Belos solver 'Block "
                                "GMRES' ('Solver/Method')."))
      << unknown;
  EXPECT_TRUE(mentions(unknown, "Did you mean 'Solver/Belos/Maximum Iterations'?")) << unknown;
  // A GMRES parameter is not TFQMR's.
  Teuchos::ParameterList numBlocks;
  numBlocks.set("Num Blocks", 40);
  const std::string other = inputErrorMessage([&] { readSolverParameters(validatedSolverList("TFQMR", numBlocks)); });
  EXPECT_TRUE(mentions(other, "'Solver/Belos/Num Blocks' is not a parameter of the Belos solver 'TFQMR'")) << other;
  Teuchos::ParameterList wrongType;
  wrongType.set("Num Blocks", "many");
  const std::string type =
      inputErrorMessage([&] { readSolverParameters(validatedSolverList("Block GMRES", wrongType)); });
  EXPECT_TRUE(mentions(type, "'Solver/Belos/Num Blocks' has type string")) << type;
  // A value Belos refuses when it takes the settings, at start-up too.
  Teuchos::ParameterList recycled;
  recycled.set("Num Recycled Blocks", 60);
  const std::string value = inputErrorMessage([&] { readSolverParameters(validatedSolverList("GCRODR", recycled)); });
  EXPECT_TRUE(mentions(value, "The Belos solver 'GCRODR' refuses its settings")) << value;
  EXPECT_TRUE(mentions(value, "\"Num Recycled Blocks\" parameter must be less than the \"Num Blocks\"")) << value;
}

TEST(KrylovMethod, DeckReadsTheMethodAndTheBelosEntries)
{
  Teuchos::ParameterList defaults("deck");
  declareOperatorParameters(defaults);
  const SolverParameters plain = readSolverParameters(defaults.sublist("Solver"));
  EXPECT_EQ(plain.method, "Block GMRES");
  EXPECT_EQ(plain.belos.numParams(), 0);
  Teuchos::ParameterList belos;
  belos.set("Num Recycled Blocks", 3);
  belos.set("Convergence Tolerance", 1); // an integer where Belos takes a real
  const SolverParameters gcrodr = readSolverParameters(validatedSolverList("GCRODR", belos));
  EXPECT_EQ(gcrodr.method, "GCRODR");
  EXPECT_EQ(gcrodr.belos.get<int>("Num Recycled Blocks"), 3);
  EXPECT_TRUE(gcrodr.belos.isType<double>("Convergence Tolerance"));
}

} // namespace
