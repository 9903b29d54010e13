// A scene's membranes on 2 ranks: each cell's membrane mechanics live on one rank
// (CellOwnership.hpp), and what the scene hands out (loads, tensions, stretches, normals,
// the stability extremes, velocities) is the same on every rank as on one rank holding
// every membrane. Three cells, two of level 2 and one of level 1, so that each rank owns
// some: 642, 162 and 642 nodes put cell 0 on rank 0 and cells 1 and 2 on rank 1.
#include "SceneTestDecks.hpp"
#include "capsula/testing/MpiTesting.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/scene/Scene.hpp>
#include <capsula/scene/UnfoldedMembranes.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

#include <Teuchos_DefaultSerialComm.hpp>
#include <Tpetra_Core.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace {

namespace scene = capsula::scene;
using capsula::testing::allRanks;

Teuchos::RCP<Teuchos::ParameterList> threeCells()
{
  return scene::testing::smallDeck(2, 2.0, false, [](Teuchos::ParameterList& d) {
    auto& cells = d.sublist("Cells");
    cells.sublist("Cell 1") = cells.sublist("Cell 0");
    cells.sublist("Cell 1").set("Center", scene::testing::realArray({3.0, 2.0, 0.0}));
    cells.sublist("Cell 1").set("Mesh level", 1);
    cells.sublist("Cell 2") = cells.sublist("Cell 0");
    cells.sublist("Cell 2").set("Center", scene::testing::realArray({6.0, 2.0, 0.0}));
  });
}

scene::Scene sceneOn(const Teuchos::ParameterList& deck, const Teuchos::RCP<const Teuchos::Comm<int>>& comm)
{
  static const auto kernels = capsula::operators::builtInKernels();
  return scene::Scene(scene::describeScene(deck), deck, comm, kernels);
}

// The largest |a - b| over two arrays, or infinity if their sizes differ.
double largestDifference(const std::vector<double>& a, const std::vector<double>& b)
{
  if (a.size() != b.size()) {
    return HUGE_VAL;
  }
  double largest = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    largest = std::max(largest, std::abs(a[k] - b[k]));
  }
  return largest;
}

std::string stateOutsideDomain(const std::function<void()>& action)
{
  try {
    action();
  } catch (const capsula::timeint::StateOutsideDomain& e) {
    return e.what();
  }
  return "(nothing thrown)";
}

TEST(SceneCellsRanks, EachMembraneLivesOnItsOwnerOnly)
{
  const auto comm = Tpetra::getDefaultComm();
  ASSERT_EQ(comm->getSize(), 2);
  const auto deck = threeCells();
  const scene::Scene s = sceneOn(*deck, comm);
  const scene::CellOwnership& ownership = s.cellOwnership();
  bool ok = ownership.owner(0) == 0 && ownership.owner(1) == 1 && ownership.owner(2) == 1;
  ok = ok && ownership.numOwned() == (comm->getRank() == 0 ? 1 : 2);
  for (int c = 0; c < 3; ++c) {
    if (ownership.owns(c)) {
      ok = ok && s.membrane(c).referencePositions() == s.referencePositions(c);
    } else {
      try {
        (void)s.membrane(c);
        ok = false;
      } catch (const capsula::core::Error& e) {
        ok = ok &&
             std::string(e.what()).find("'Cells/Cell " + std::to_string(c) + "' is held by rank") != std::string::npos;
      }
    }
  }
  EXPECT_TRUE(allRanks(*comm, ok));
}

// Every membrane number comes from one rank's arithmetic, whatever the ranks: tolerance 0.
// The velocities sum the single layer over the rows each rank owns, the same arithmetic per
// row as on one rank: held to 1e-13 of the largest, round-off should the order differ.
TEST(SceneCellsRanks, FieldsMatchOneRankHoldingEveryMembrane)
{
  const auto comm = Tpetra::getDefaultComm();
  const auto deck = threeCells();
  scene::Scene distributed = sceneOn(*deck, comm);
  scene::Scene serial = sceneOn(*deck, Teuchos::rcp(new Teuchos::SerialComm<int>()));
  // Stretched along x and squeezed along y about y = 2: every membrane in tension and
  // compression, so the loads and tensions are far from zero.
  std::vector<double> x = distributed.initialPositions();
  for (std::size_t i = 0; i < x.size(); i += 3) {
    x[i] *= 1.05;
    x[i + 1] = 2.0 + 0.97 * (x[i + 1] - 2.0);
  }
  const scene::SceneFields a = distributed.evaluate(0.0, x);
  const scene::SceneFields b = serial.evaluate(0.0, x);
  bool same = largestDifference(a.elementLoads, b.elementLoads) == 0.0 &&
              largestDifference(a.loadDensity, b.loadDensity) == 0.0 &&
              largestDifference(a.principalTensions, b.principalTensions) == 0.0 &&
              largestDifference(a.stretches, b.stretches) == 0.0 &&
              largestDifference(a.nodeNormals, b.nodeNormals) == 0.0 && a.membraneExtremes.size() == 3 &&
              b.membraneExtremes.size() == 3;
  for (std::size_t c = 0; same && c < 3; ++c) {
    same = a.membraneExtremes[c].mostCompressiveTension == b.membraneExtremes[c].mostCompressiveTension &&
           a.membraneExtremes[c].leastPrincipalStiffness == b.membraneExtremes[c].leastPrincipalStiffness;
  }
  double largestLoad = 0.0, largestVelocity = 0.0;
  for (const double v : b.elementLoads) {
    largestLoad = std::max(largestLoad, std::abs(v));
  }
  for (const double v : b.velocities) {
    largestVelocity = std::max(largestVelocity, std::abs(v));
  }
  EXPECT_TRUE(allRanks(*comm, same));
  EXPECT_TRUE(allRanks(*comm, largestLoad > 0.1)); // the comparison could fail
  EXPECT_TRUE(allRanks(*comm, largestDifference(a.velocities, b.velocities) <= 1e-13 * largestVelocity));
}

// A folded membrane stops every rank with the same message, whichever rank holds it, and
// with two folded cells the lower one is named, as on one rank.
TEST(SceneCellsRanks, AFoldedMembraneStopsEveryRankNamingTheFirstFoldedCell)
{
  const auto comm = Tpetra::getDefaultComm();
  const auto deck = threeCells();
  scene::Scene s = sceneOn(*deck, comm);
  // Node 0 of a level-2 cell (a vertex at the centre's x) slides along the surface by
  // 0.6, twice the edge, past its neighbours: the elements it moves over turn inside out.
  const auto fold = [&](std::vector<double>& x, int cell) {
    x[3 * static_cast<std::size_t>(s.nodeOffset(cell))] += 0.6;
  };
  std::vector<double> x = s.initialPositions();
  fold(x, 2);
  const std::string onlyLast = stateOutsideDomain([&] { scene::requireUnfoldedMembranes(s, x); });
  fold(x, 0);
  const std::string both = stateOutsideDomain([&] { scene::requireUnfoldedMembranes(s, x); });
  std::vector<double> u;
  const std::string evaluated = stateOutsideDomain([&] { s.velocity(0.5, x, u); });
  const bool ok =
      onlyLast.find("the membrane of 'Cells/Cell 2' failed: the membrane is folded at node ") == 0 &&
      both.find("the membrane of 'Cells/Cell 0' failed: the membrane is folded at node ") == 0 &&
      evaluated.find("At t = 0.5, the membrane of 'Cells/Cell 0' failed: the membrane is folded") != std::string::npos;
  EXPECT_TRUE(allRanks(*comm, ok)) << onlyLast << "\n" << both << "\n" << evaluated;
}

} // namespace
