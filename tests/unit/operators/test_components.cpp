// The pieces under the operators: polar rules, the element map, the contracted kernels,
// deck parameters, the kernel registry, the surfaces and the Tpetra operator.
#include "OperatorTesting.hpp"

#include <algorithm>

#include <capsula/core/Error.hpp>
#include <capsula/greens/FreeSpace3D.hpp>
#include <capsula/greens/Wall3D.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/operators/BuiltInKernels.hpp>
#include <capsula/operators/ContractedKernels.hpp>
#include <capsula/operators/ElementIntegrals.hpp>
#include <capsula/operators/KernelChoice.hpp>
#include <capsula/operators/OperatorParameters.hpp>
#include <capsula/operators/PolarRules.hpp>
#include <capsula/operators/SecondKindOperator.hpp>
#include <capsula/quadrature/GaussLegendre.hpp>

#include <Teuchos_ParameterList.hpp>
#include <Tpetra_Core.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace {

using namespace capsula;
using namespace capsula::operators;
using mesh::Vec3;
namespace ot = capsula::operators::testing;

// --- polar rules -------------------------------------------------------------------------

template <class Integrand>
double integrate(const ParametricRule& rule, Integrand&& f)
{
  double sum = 0.0;
  for (int k = 0; k < rule.size(); ++k) {
    sum += rule.weight[k] * f(rule.xi[k], rule.eta[k]);
  }
  return sum;
}

// The polar rules are built in the equilateral image of the parametric triangle
// (PolarRules.cpp): (x, y) = (xi + eta / 2, sqrt(3)/2 eta), dxi deta = (2 / sqrt 3) dx dy.
double equilateralDistance(double xi, double eta, double apexX, double apexY)
{
  return std::hypot(xi + 0.5 * eta - apexX, std::sqrt(3.0) / 2.0 * eta - apexY);
}

TEST(PolarRules, VertexRuleIntegratesInverseDistanceExactly)
{
  // int_T 1/rho dxi deta around any vertex, rho the equilateral-frame distance:
  // (2/sqrt 3) * p [asinh(1/(2p)) - asinh(-1/(2p))] with p = sqrt(3)/2, i.e. ln 3.
  // In u = asinh(tan(theta - theta_perp)) the integrand r' / rho is constant: exact with
  // ONE point per direction (round-off), at each of the three vertices alike.
  const auto gauss = quadrature::gaussLegendre(1, 0.0, 1.0);
  const double apex[3][2] = {{0.0, 0.0}, {1.0, 0.0}, {0.5, std::sqrt(3.0) / 2.0}};
  ParametricRule rule;
  for (int vertex = 0; vertex < 3; ++vertex) {
    singularRule(vertex, mesh::ShapeParameters{}, gauss, rule);
    EXPECT_NEAR(
        integrate(rule, [&](double x,
                            double y) { return 1.0 / equilateralDistance(x, y, apex[vertex][0], apex[vertex][1]); }),
        std::log(3.0), 1e-15)
        << "vertex " << vertex;
  }
  // The area 1/2 needs a few points (cosh u is not constant): 10 reach round-off.
  singularRule(0, mesh::ShapeParameters{}, quadrature::gaussLegendre(10, 0.0, 1.0), rule);
  EXPECT_NEAR(integrate(rule, [](double, double) { return 1.0; }), 0.5, 1e-15);
}

TEST(PolarRules, VertexRulesDoNotDependOnTheVertexNumbering)
{
  // Fixed bug (two-cell symmetry): the rule around vertex k must be the rule around
  // vertex 0 with the barycentric coordinates relabelled, so that mirror-image meshes
  // (whose elements list their vertices in the other order) get mirror-image integrals.
  // Built in the right-angled parametric triangle, the rules at the right angle and at a
  // 45-degree corner differed, and side-by-side cells lost symmetry at the 1e-5 level.
  const auto gauss = quadrature::gaussLegendre(6, 0.0, 1.0);
  ParametricRule reference, rule;
  singularRule(0, mesh::ShapeParameters{}, gauss, reference);
  // Barycentric (l0, l1, l2) of point k of the vertex-0 rule; vertex v's rule must hold the
  // point with l_v = l0 and the other two in either order (the rule is symmetric).
  for (int vertex = 1; vertex < 3; ++vertex) {
    singularRule(vertex, mesh::ShapeParameters{}, gauss, rule);
    ASSERT_EQ(rule.size(), reference.size());
    for (int k = 0; k < reference.size(); ++k) {
      const double l0 = 1.0 - reference.xi[k] - reference.eta[k];
      const double l[3] = {1.0 - rule.xi[k] - rule.eta[k], rule.xi[k], rule.eta[k]};
      const double others[2] = {l[(vertex + 1) % 3], l[(vertex + 2) % 3]};
      EXPECT_NEAR(l[vertex], l0, 1e-15) << "vertex " << vertex << " point " << k;
      EXPECT_NEAR(others[0], reference.xi[k], 1e-15) << "vertex " << vertex << " point " << k;
      EXPECT_NEAR(others[1], reference.eta[k], 1e-15) << "vertex " << vertex << " point " << k;
      EXPECT_NEAR(rule.weight[k], reference.weight[k], 1e-15) << "vertex " << vertex << " point " << k;
    }
  }
}

TEST(PolarRules, EveryNodeRuleCoversTheTriangle)
{
  // For each of the six nodes, with uneven midside nodes, the rule covers the whole
  // triangle: smooth integrands converge spectrally (in the radius a polynomial, in u an
  // entire function of sinh u and cosh u), to round-off at 12 points.
  const mesh::ShapeParameters shape{0.45, 0.55, 0.4};
  const auto gauss = quadrature::gaussLegendre(12, 0.0, 1.0);
  ParametricRule rule;
  for (int node = 0; node < 6; ++node) {
    singularRule(node, shape, gauss, rule);
    EXPECT_NEAR(integrate(rule, [](double, double) { return 1.0; }), 0.5, 1e-13) << "node " << node;
    // int_T xi^2 eta dxi deta = 2! 1! / 5! = 1/60.
    EXPECT_NEAR(integrate(rule, [](double x, double y) { return x * x * y; }), 1.0 / 60.0, 1e-13) << "node " << node;
  }
}

TEST(PolarRules, MidsideRuleIntegratesInverseDistanceExactly)
{
  // Around P = (alpha, 0) (equilateral frame: (alpha, 0) too): int_T 1/rho dxi deta =
  // (2/sqrt 3) sum over the sub-triangles (P, A, B) of p [asinh(sigma_B / p) -
  // asinh(sigma_A / p)], p the distance from P to side AB and sigma the positions of A
  // and B along it from the foot of the perpendicular, all in the equilateral frame.
  constexpr double alpha = 0.4;
  const double h = std::sqrt(3.0) / 2.0;
  const mesh::ShapeParameters shape{alpha, 0.5, 0.5};
  const auto piece = [](double ax, double ay, double bx, double by) {
    const double lx = bx - ax, ly = by - ay, l = std::hypot(lx, ly);
    const double sigmaA = ((ax - alpha) * lx + ay * ly) / l;
    const double p = std::abs((ax - alpha) * ly - ay * lx) / l;
    return p * (std::asinh((sigmaA + l) / p) - std::asinh(sigmaA / p));
  };
  const double exact = 2.0 / std::sqrt(3.0) * (piece(1.0, 0.0, 0.5, h) + piece(0.5, h, 0.0, 0.0));
  ParametricRule rule;
  singularRule(3, shape, quadrature::gaussLegendre(1, 0.0, 1.0), rule);
  EXPECT_NEAR(integrate(rule, [&](double x, double y) { return 1.0 / equilateralDistance(x, y, alpha, 0.0); }), exact,
              1e-15);
}

// --- element map -------------------------------------------------------------------------

TEST(ElementMap, MatchesTheMeshElementGeometry)
{
  // The quadratic re-interpolation is exact: position, h_s n and phi agree with
  // mesh::evaluateSurfacePoint and mesh::shapeFunctions to round-off.
  const auto surface = mesh::makeEllipsoid(1, Vec3(1.3, 0.8, 1.0));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int e = 0; e < surface.numElements(); e += 7) {
    const auto x = surface.elementNodes(e);
    // Uneven midside placement to exercise alpha, beta, gamma != 1/2.
    const mesh::ShapeParameters shape{0.43, 0.56, 0.61};
    const ElementMap map(x, shape);
    for (int k = 0; k < 5; ++k) {
      double xi = uniform(random), eta = uniform(random);
      if (xi + eta > 1.0) {
        xi = 1.0 - xi;
        eta = 1.0 - eta;
      }
      const ElementSample s = map.sample(xi, eta, 0.25);
      const mesh::SurfacePoint p = mesh::evaluateSurfacePoint(x, shape, xi, eta);
      double phi[6];
      mesh::shapeFunctions(shape, xi, eta, phi);
      for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(s.x[i], p.position[i], 1e-14);
        EXPECT_NEAR(s.weightedNormal[i], 0.25 * p.metric * p.normal[i], 1e-14);
      }
      EXPECT_NEAR(s.weight, 0.25 * p.metric, 1e-14);
      for (int a = 0; a < 6; ++a) {
        EXPECT_NEAR(s.phi[a], phi[a], 1e-13);
      }
    }
  }
}

// --- contracted kernels ------------------------------------------------------------------

template <class Contracted, class Tensors>
void expectContractionsMatchTensors()
{
  std::mt19937 random(11);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    const double x[3] = {uniform(random), 1.2 + uniform(random), uniform(random)};
    const double x0[3] = {uniform(random), 1.2 + uniform(random), uniform(random)};
    const double f[3] = {uniform(random), uniform(random), uniform(random)};
    const double a[3] = {uniform(random), uniform(random), uniform(random)};
    double G[3][3], T[3][3][3];
    Tensors::stokeslet(x, x0, G);
    Tensors::stresslet(x, x0, T);
    double single[3] = {0.0, 0.0, 0.0}, dbl[3] = {0.0, 0.0, 0.0};
    Contracted::addSingleLayerTerm(x, x0, f, single);
    Contracted::addDoubleLayerTerm(x, x0, f, a, dbl);
    double scaleG = 0.0, scaleT = 0.0;
    double expectG[3] = {0.0, 0.0, 0.0}, expectT[3] = {0.0, 0.0, 0.0};
    for (int j = 0; j < 3; ++j) {
      for (int i = 0; i < 3; ++i) {
        expectG[j] += G[i][j] * f[i];
        scaleG += std::abs(G[i][j] * f[i]);
        for (int l = 0; l < 3; ++l) {
          expectT[j] += T[i][j][l] * f[i] * a[l];
          scaleT += std::abs(T[i][j][l] * f[i] * a[l]);
        }
      }
    }
    for (int j = 0; j < 3; ++j) {
      // Round-off of sums of ~30 terms, relative to the sum of their sizes.
      EXPECT_NEAR(single[j], expectG[j], 1e-14 * scaleG);
      EXPECT_NEAR(dbl[j], expectT[j], 1e-14 * scaleT);
    }
    // The double-layer matrix T_ijk a_k of the special rules, entry by entry (a wrong sign
    // or index in any one term moves an entry by O(its size)).
    double M[9] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    Contracted::addDoubleLayerMatrix(x, x0, a, M);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        double expect = 0.0, scale = 0.0;
        for (int l = 0; l < 3; ++l) {
          expect += T[i][j][l] * a[l];
          scale += std::abs(T[i][j][l] * a[l]);
        }
        EXPECT_NEAR(M[3 * i + j], expect, 1e-14 * std::max(scale, scaleT));
      }
    }
  }
}

TEST(ContractedKernels, FreeSpaceMatchesGreensTensors)
{
  expectContractionsMatchTensors<FreeSpace3DKernel, greens::FreeSpace3D>();
}

TEST(ContractedKernels, WallMatchesGreensTensors)
{
  expectContractionsMatchTensors<Wall3DKernel, greens::Wall3D>();
}

TEST(ContractedKernels, WallTermsVanishExactlyForAPoleOnTheWall)
{
  // No slip: a target on the wall gets nothing from any source, to the last bit (free
  // and image terms are evaluated alike), so no near-singular work is spent there.
  const double x[3] = {0.3, 0.8, -0.2}, x0[3] = {-0.1, 0.0, 0.4};
  const double f[3] = {0.2, -0.5, 0.9}, a[3] = {0.4, 0.1, -0.3};
  double single[3] = {0.0, 0.0, 0.0}, dbl[3] = {0.0, 0.0, 0.0};
  Wall3DKernel::addSingleLayerTerm(x, x0, f, single);
  Wall3DKernel::addDoubleLayerTerm(x, x0, f, a, dbl);
  double M[9] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  Wall3DKernel::addDoubleLayerMatrix(x, x0, a, M);
  for (int j = 0; j < 3; ++j) {
    EXPECT_EQ(single[j], 0.0);
    EXPECT_EQ(dbl[j], 0.0);
  }
  for (const double m : M) {
    EXPECT_EQ(m, 0.0);
  }
  EXPECT_TRUE(KernelTraits<Wall3DKernel>::vanishesAt(x0));
}

TEST(ContractedKernels, GenericContractionIsUsedWithoutHooks)
{
  // greens::Wall3D has no hooks: KernelTraits contracts its tensors; same numbers.
  const double x[3] = {0.3, 1.1, -0.2}, x0[3] = {-0.1, 0.7, 0.4}, f[3] = {0.2, -0.5, 0.9};
  double generic[3] = {0.0, 0.0, 0.0}, fast[3] = {0.0, 0.0, 0.0};
  addSingleLayerTerm<greens::Wall3D>(x, x0, f, generic);
  addSingleLayerTerm<Wall3DKernel>(x, x0, f, fast);
  for (int j = 0; j < 3; ++j) {
    EXPECT_NEAR(generic[j], fast[j], 1e-14);
  }
  double genericMatrix[9] = {}, fastMatrix[9] = {};
  addDoubleLayerMatrix<greens::Wall3D>(x, x0, f, genericMatrix);
  addDoubleLayerMatrix<Wall3DKernel>(x, x0, f, fastMatrix);
  for (int k = 0; k < 9; ++k) {
    EXPECT_NEAR(genericMatrix[k], fastMatrix[k], 1e-13);
  }
}

// --- parameters ----------------------------------------------------------------------------

TEST(OperatorParameters, DeclaredDefaultsReadBack)
{
  Teuchos::ParameterList deck;
  declareOperatorParameters(deck);
  const DiscretisationParameters d = readDiscretisationParameters(deck.sublist("Discretisation"));
  const SolverParameters s = readSolverParameters(deck.sublist("Solver"));
  const DiscretisationParameters dd;
  const SolverParameters sd;
  EXPECT_EQ(d.quadraturePoints, dd.quadraturePoints);
  EXPECT_EQ(d.singularQuadraturePoints, dd.singularQuadraturePoints);
  EXPECT_EQ(d.nearSingularTolerance, dd.nearSingularTolerance);
  EXPECT_EQ(d.nearSingularDistance, dd.nearSingularDistance);
  EXPECT_EQ(d.regularNeighbourRings, dd.regularNeighbourRings);
  // The 3D deck: its own GMRES tolerance and the warm start on.
  EXPECT_EQ(s.tolerance, kSurfaceSolverTolerance);
  EXPECT_TRUE(s.warmStart);
  EXPECT_EQ(s.restart, sd.restart);
  EXPECT_EQ(s.maximumIterations, sd.maximumIterations);
  EXPECT_EQ(s.method, "Block GMRES");
  EXPECT_EQ(s.belos.numParams(), 0);
  EXPECT_TRUE(deck.sublist("Solver").isSublist("Belos"));
  // The 2D contour's list keeps the struct's tolerance and has the warm start on too.
  Teuchos::ParameterList contour;
  declareSolverParameters(contour);
  EXPECT_TRUE(contour.isParameter("Warm start"));
  const SolverParameters c = readSolverParameters(contour);
  EXPECT_EQ(c.tolerance, sd.tolerance);
  EXPECT_TRUE(c.warmStart);
  EXPECT_EQ(c.method, "Block GMRES");
  EXPECT_TRUE(contour.isSublist("Belos"));
  // A list without the keys (a caller that never declared them) reads as no warm start and
  // the default method.
  Teuchos::ParameterList bare;
  bare.set("Tolerance", 1e-8);
  bare.set("Restart", 30);
  bare.set("Maximum iterations", 100);
  EXPECT_FALSE(readSolverParameters(bare).warmStart);
  EXPECT_EQ(readSolverParameters(bare).method, "Block GMRES");
}

TEST(OperatorParameters, RuleWithoutTriangleRuleIsRejectedByName)
{
  Teuchos::ParameterList deck;
  declareOperatorParameters(deck);
  deck.sublist("Discretisation").set("Quadrature points", 5);
  try {
    readDiscretisationParameters(deck.sublist("Discretisation"));
    FAIL() << "N_Q = 5 has no rule";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Quadrature points"), std::string::npos) << e.what();
  }
  SolverParameters bad;
  bad.tolerance = 0.0;
  EXPECT_THROW(validate(bad), core::InputError);
}

// --- registry and surfaces -----------------------------------------------------------------

TEST(KernelRegistry, BuiltInsAndUnknownNames)
{
  const KernelRegistry registry = builtInKernels();
  EXPECT_EQ(registry.names(), (std::vector<std::string>{"FreeSpace", "Wall"}));
  auto solver =
      registry.create("Wall", ot::serialComm(),
                      CellSurfaces({mesh::makeSphere(0, 0.5, {Vec3(0, 1, 0), mesh::Mat3::Identity()})}, 1.0), {}, {});
  EXPECT_EQ(solver->kernelName(), "plane wall 3D");
  try {
    registry.create("Wal", ot::serialComm(), CellSurfaces({mesh::makeSphere(0, 0.5)}, 1.0), {}, {});
    FAIL() << "unknown kernel";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Did you mean 'Wall'"), std::string::npos) << e.what();
  }
  KernelRegistry copy = registry;
  EXPECT_THROW(copy.add("Wall", "again", solverFactory<Wall3DKernel>()), core::InputError);
  // "Auto" is the deck's automatic choice (KernelChoice.hpp), never a kernel.
  EXPECT_THROW(copy.add("Auto", "automatic", solverFactory<FreeSpace3DKernel>()), core::InputError);
  EXPECT_EQ(registry.infos().at("Wall").domain, FluidDomain::AboveWall);
  EXPECT_EQ(registry.infos().at("FreeSpace").domain, FluidDomain::Unbounded);
}

// The kernel a deck gets in each domain (KernelChoice.hpp): Auto keeps FreeSpace and Wall
// where they serve, picks a registered kernel that serves a channel or a periodic box, and a
// domain nobody serves, or a kernel named for another domain, is refused naming the keys.
// "PeriodicChannel" stands for an operator library's kernel; only its KernelInfo matters here.
TEST(KernelChoice, EachDomainGetsAKernelThatServesIt)
{
  KernelRegistry registry = builtInKernels();
  const Teuchos::ParameterList automatic;
  domain::DomainShape periodicChannel;
  periodicChannel.channelHeight = 8.0;
  periodicChannel.periodX = 16.0;
  const domain::Domain channelBox(periodicChannel);
  EXPECT_EQ(readKernelChoice(automatic, registry.infos(), domain::Domain::aboveWall()).name, "Wall");
  EXPECT_EQ(readKernelChoice(automatic, registry.infos(), domain::Domain::unbounded()).name, "FreeSpace");
  const auto refusal = [&](const Teuchos::ParameterList& list, const domain::Domain& d) -> std::string {
    try {
      readKernelChoice(list, registry.infos(), d);
    } catch (const core::InputError& e) {
      return e.what();
    }
    return "accepted";
  };
  const std::string none = refusal(automatic, channelBox);
  EXPECT_NE(none.find("No registered Green's function serves a channel 0 < y < 8, periodic along x (L_x = 16) "
                      "('Wall/Enabled' = true, 'Wall/Channel height' = 8, 'Domain/Periodic length x' = 16)"),
            std::string::npos)
      << none;
  registry.add("PeriodicChannel", KernelInfo{"A periodic channel.", FluidDomain::Channel, Teuchos::null, true},
               solverFactory<FreeSpace3DKernel>());
  // A periodic kernel is periodic along x and z: it serves the box periodic along both, and
  // a box periodic along x only is still served by none.
  domain::DomainShape doublyPeriodicChannel = periodicChannel;
  doublyPeriodicChannel.periodZ = 12.0;
  const domain::Domain channelBoxXZ(doublyPeriodicChannel);
  EXPECT_EQ(readKernelChoice(automatic, registry.infos(), channelBoxXZ).name, "PeriodicChannel");
  EXPECT_TRUE(servesDomain(registry.infos().at("PeriodicChannel"), channelBoxXZ));
  EXPECT_FALSE(servesDomain(registry.infos().at("PeriodicChannel"), channelBox));
  EXPECT_FALSE(servesDomain(registry.infos().at("PeriodicChannel"), domain::Domain::channel(8.0)));
  // The built-in kernels still get the domains they serve with the new one registered.
  EXPECT_EQ(readKernelChoice(automatic, registry.infos(), domain::Domain::aboveWall()).name, "Wall");
  Teuchos::ParameterList named;
  named.set("Kernel", std::string("Wall"));
  const std::string wallInChannel = refusal(named, channelBox);
  EXPECT_NE(wallInChannel.find("'Operator/Kernel' = Wall is for the fluid above the wall y = 0 without periodic "
                               "directions but the deck ('Wall/Enabled' = true, 'Wall/Channel height' = 8, "
                               "'Domain/Periodic length x' = 16) describes a channel"),
            std::string::npos)
      << wallInChannel;
  named.set("Kernel", std::string("PeriodicChannel"));
  const std::string periodicAboveWall = refusal(named, domain::Domain::aboveWall());
  EXPECT_NE(periodicAboveWall.find("is for a channel between two walls, periodic along x and z"), std::string::npos)
      << periodicAboveWall;
}

TEST(CellSurfaces, NumbersCellsConsecutivelyAndRejectsBadRatios)
{
  const CellSurfaces surfaces({mesh::makeSphere(0, 1.0), mesh::makeSphere(1, 1.0)}, {1.0, 3.0});
  EXPECT_EQ(surfaces.numNodes(), 42 + 162);
  EXPECT_EQ(surfaces.numElements(), 20 + 80);
  EXPECT_EQ(surfaces.cellOfNode(41), 0);
  EXPECT_EQ(surfaces.cellOfNode(42), 1);
  EXPECT_EQ(surfaces.cellOfElement(20), 1);
  EXPECT_EQ(surfaces.elementNodes(20)[0], 42 + surfaces.cell(1).element(0)[0]);
  EXPECT_FALSE(surfaces.allViscosityRatiosOne());
  EXPECT_THROW(CellSurfaces({mesh::makeSphere(0, 1.0)}, {0.0}), core::InputError);
  EXPECT_THROW(CellSurfaces({mesh::makeSphere(0, 1.0)}, std::vector<double>{}), core::InputError);
}

TEST(LayerPotentials, WallKernelRejectsNodesBelowTheWall)
{
  EXPECT_THROW(ot::makeSolver("Wall", mesh::makeSphere(1, 1.0)), core::InputError);
  EXPECT_NO_THROW(ot::makeSolver("FreeSpace", mesh::makeSphere(1, 1.0)));
}

// --- the Tpetra operator -------------------------------------------------------------------

TEST(SecondKindOperator, HonoursAlphaBetaAndRejectsTranspose)
{
  using MV = Tpetra::MultiVector<double>;
  const auto comm = ot::serialComm();
  const int numNodes = 4;
  auto map = Teuchos::rcp(new Tpetra::Map<>(3 * numNodes, 0, comm));
  // A stand-in double layer: DL[u]_t = sum of all entries of u (every row sees every node).
  const auto layer = [](const double* u, double* rows) {
    double sum = 0.0;
    for (int k = 0; k < 3 * numNodes; ++k) {
      sum += u[k];
    }
    for (int k = 0; k < 3 * numNodes; ++k) {
      rows[k] = sum;
    }
  };
  const SecondKindOperator A(map, layer, std::vector<double>(numNodes, 2.0), std::vector<double>(numNodes, 0.5));
  EXPECT_FALSE(A.hasTransposeApply());
  MV x(map, 1), y(map, 1);
  {
    auto data = x.getDataNonConst(0);
    for (int k = 0; k < 3 * numNodes; ++k) {
      data[k] = k + 1.0;
    }
    y.putScalar(std::nan(""));
  }
  // A x = x - 0.5 * (2 * sum x) = x - 78; beta = 0 must ignore the NaN in y.
  A.apply(x, y, Teuchos::NO_TRANS, 2.0, 0.0);
  {
    const auto data = y.getData(0);
    for (int k = 0; k < 3 * numNodes; ++k) {
      EXPECT_DOUBLE_EQ(data[k], 2.0 * ((k + 1.0) - 78.0));
    }
  }
  A.apply(x, y, Teuchos::NO_TRANS, 1.0, -1.0); // y = A x - y = -(A x)
  {
    const auto data = y.getData(0);
    for (int k = 0; k < 3 * numNodes; ++k) {
      EXPECT_DOUBLE_EQ(data[k], -((k + 1.0) - 78.0));
    }
  }
  EXPECT_THROW(A.apply(x, y, Teuchos::TRANS, 1.0, 0.0), std::invalid_argument);
  EXPECT_EQ(A.applications(), 2);
}

TEST(SecondKindOperator, TwoUnknownsPerNodeWithAPrescribedRow)
{
  // The 2D form: no density scale, row scale c everywhere but 0 at node 1 (a tether),
  // whose two rows are then the identity.
  using MV = Tpetra::MultiVector<double>;
  const auto comm = ot::serialComm();
  const int numNodes = 3;
  auto map = Teuchos::rcp(new Tpetra::Map<>(2 * numNodes, 0, comm));
  const auto layer = [](const double* u, double* rows) {
    double sum = 0.0;
    for (int k = 0; k < 2 * numNodes; ++k) {
      sum += u[k];
    }
    for (int k = 0; k < 2 * numNodes; ++k) {
      rows[k] = sum + k; // differs per row, so a wrong row index shows
    }
  };
  const SecondKindOperator A(map, layer, {}, {0.25, 0.0, 0.25}, 2);
  MV x(map, 1), y(map, 1);
  {
    auto data = x.getDataNonConst(0);
    for (int k = 0; k < 2 * numNodes; ++k) {
      data[k] = k + 1.0; // sum 21
    }
  }
  A.apply(x, y);
  const auto data = y.getData(0);
  for (int k = 0; k < 2 * numNodes; ++k) {
    const double expected = (k / 2 == 1) ? k + 1.0 : (k + 1.0) - 0.25 * (21.0 + k);
    EXPECT_DOUBLE_EQ(data[k], expected) << "row " << k;
  }
  // One factor per owned node, and 2 or 3 unknowns per node.
  EXPECT_THROW(SecondKindOperator(map, layer, {}, {0.25, 0.25}, 2), core::Error);
  EXPECT_THROW(SecondKindOperator(map, layer, {}, {0.25, 0.25, 0.25}, 4), core::Error);
}

} // namespace
