// GMRES's warm start (Solver/Warm start, lambda != 1): the scene starts each right-hand
// side's solve from its last solutions (operators::WarmStartHistory) and outputs start cold
// (the checkpoint carries the history: run/test_mesh_events.cpp).
#include "SceneTestDecks.hpp"

#include <capsula/operators/KernelRegistry.hpp>
#include <capsula/scene/Scene.hpp>
#include <capsula/scene/SceneDescription.hpp>

#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

namespace scene = capsula::scene;
using scene::testing::makeScene;
using scene::testing::smallDeck;

Teuchos::RCP<Teuchos::ParameterList> lambdaFiveDeck(bool warmStart)
{
  return smallDeck(1, 1.6, true, [&](Teuchos::ParameterList& d) {
    d.sublist("Flow").set("Viscosity ratio", 5.0);
    d.sublist("Solver").set("Warm start", warmStart);
  });
}

double largest(const std::vector<double>& v)
{
  double m = 0.0;
  for (const double x : v) {
    m = std::max(m, std::abs(x));
  }
  return m;
}

TEST(SceneWarmStart, VelocityKeepsItsSolutionsAndOutputsStartCold)
{
  auto s = makeScene(*lambdaFiveDeck(true));
  ASSERT_NE(s.gmresWarmStart(), nullptr);
  EXPECT_TRUE(s.gmresWarmStart()->empty());
  std::vector<double> x = s.initialPositions(), u;
  s.velocity(0.0, x, u);
  ASSERT_EQ(s.gmresWarmStart()->size(), 1);
  EXPECT_EQ(s.gmresWarmStart()->solutions(), u);
  // A step later (the nodes moved by dt u): the output's cold solve leaves the history alone.
  for (std::size_t k = 0; k < x.size(); ++k) {
    x[k] += 0.02 * u[k];
  }
  const auto cold = s.evaluate(0.02, x);
  EXPECT_EQ(s.gmresWarmStart()->size(), 1);
  std::vector<double> warm;
  s.velocity(0.02, x, warm);
  EXPECT_EQ(s.gmresWarmStart()->size(), 2);
  // Both solve to the deck's default relative residual (1e-9), and the node velocities err by
  // at most ~4x the tolerance times the largest one (measured), so they agree to 1e-8 of it;
  // they differ (different Krylov spaces), or the warm start was not used.
  double difference = 0.0;
  for (std::size_t k = 0; k < warm.size(); ++k) {
    difference = std::max(difference, std::abs(warm[k] - cold.solverVelocities[k]));
  }
  EXPECT_LT(difference, 1e-8 * largest(warm));
  EXPECT_GT(difference, 0.0);

  // Warm start off: no history, every solve starts from the right-hand side.
  auto off = makeScene(*lambdaFiveDeck(false));
  std::vector<double> v;
  off.velocity(0.0, off.initialPositions(), v);
  EXPECT_EQ(off.gmresWarmStart(), nullptr);
}

} // namespace
