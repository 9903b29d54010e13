// Bond kinetics are the same on 2 ranks as on 1: a scene on the 2-rank communicator (each
// rank advances its block of receptors, shareBondStates gathers them) against the same
// bonds advanced on a one-rank communicator on every rank, over steps that move the cell in
// and out of reach. The draws are counter-based per (seed, cell, receptor, step), so the
// states must agree to the last bit: tolerance 0.
#include "SceneTestDecks.hpp"
#include "capsula/testing/MpiTesting.hpp"

#include <capsula/scene/Scene.hpp>
#include <capsula/scene/SceneBonds.hpp>

#include <Teuchos_DefaultSerialComm.hpp>
#include <Tpetra_Core.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

namespace scene = capsula::scene;

TEST(SceneBondsRanks, StochasticBondsDoNotDependOnTheRanks)
{
  const auto comm = Tpetra::getDefaultComm();
  ASSERT_EQ(comm->getSize(), 2);
  auto deck = scene::testing::smallDeck(1, 1.03, true, [](Teuchos::ParameterList& d) {
    auto& a = d.sublist("Adhesion");
    a.set("Enabled", true);
    a.set("On-rate", 0.2); // k_on0 n_L = 20 k, k_off0 = 5 k: binding and breaking each step
    a.set("Off-rate", 5.0);
    a.set("Thermal energy", 1e-2);
    a.set("Seed", 11);
  });
  auto distributed = scene::testing::makeScene(*deck);
  scene::SceneBonds serial(distributed.description().adhesion, {distributed.cell(0)},
                           {distributed.referencePositions(0)});
  const Teuchos::SerialComm<int> one;
  std::vector<double> x = distributed.initialPositions();
  int formed = 0, broken = 0;
  bool same = true;
  for (int step = 1; step <= 30; ++step) {
    // Down and up by up to 0.02 a and along the flow: receptors enter and leave reach and
    // bonds stretch.
    std::vector<double> moved = x;
    for (std::size_t i = 0; i < moved.size(); i += 3) {
      moved[i] += 0.01 * step;
      moved[i + 1] += 0.02 * std::sin(0.7 * step);
    }
    const auto events = distributed.updateBonds(moved, 0.05, static_cast<std::uint64_t>(step));
    const auto reference =
        serial.update(0, distributed.cell(0), moved.data(), 0.05, static_cast<std::uint64_t>(step), one);
    formed += events.formed;
    broken += events.broken;
    same = same && events.formed == reference.formed && events.broken == reference.broken &&
           distributed.bonds().states(0) == serial.states(0);
  }
  EXPECT_TRUE(capsula::testing::allRanks(*comm, same));
  // Events happened, so the comparison could have failed.
  EXPECT_TRUE(capsula::testing::allRanks(*comm, formed > 10 && broken > 10)) << formed << " " << broken;
}

} // namespace
