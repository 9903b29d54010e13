// A tethered cell run on 2 ranks gives the tether force history of the same run on one rank
// (each rank repeats it with a serial communicator into a directory of its own). At
// lambda = 1 every rank evaluates whole rows of the boundary-integral equation in the same
// order and the tether is placed by every rank from the same initial shape, so the
// histories agree bit for bit: tolerance 0.
#include "SceneRunFixture.hpp"
#include "capsula/testing/MpiTesting.hpp"

#include <capsula/io/MetricsCsv.hpp>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultSerialComm.hpp>
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using namespace capsula;

TEST(TetherRanks, TetherForceHistoryDoesNotDependOnTheRankCount)
{
  const auto comm = Tpetra::getDefaultComm();
  ASSERT_EQ(comm->getSize(), 2);
  // A level-1 sphere tethered 0.05 a above the wall in shear (Ca = 0.1), adaptive RKF45 to
  // t = 0.3: the step sizes follow the error estimates, so any difference would also move
  // the output times' steps.
  const auto deck = run::testing::smallDeck(1, 1.05, true, [](Teuchos::ParameterList& d) {
    d.sublist("Time integration").set("End time", 0.3);
    d.sublist("Flow").set("Capillary number", 0.1);
    d.sublist("Tether").set("Enabled", true);
    d.sublist("Tether").set("Spring constant", 20.0);
    d.sublist("Output").set("Snapshots", false);
  });
  int pid = static_cast<int>(::getpid());
  Teuchos::broadcast(*comm, 0, &pid);
  const auto root = std::filesystem::temp_directory_path() / ("capsula-tether-ranks-" + std::to_string(pid));
  static const auto kernels = operators::builtInKernels();
  run::SceneRunOptions options;
  options.application = "test";
  options.outputDirectory = (root / "two").string();
  run::runScene(*deck, comm, options, kernels);
  options.outputDirectory = (root / ("one-" + std::to_string(comm->getRank()))).string();
  run::runScene(*deck, Teuchos::rcp(new Teuchos::SerialComm<int>), options, kernels);

  const auto two = io::readCsvTable((root / "two" / "metrics.csv").string());
  const auto one = io::readCsvTable((root / ("one-" + std::to_string(comm->getRank())) / "metrics.csv").string());
  bool same = two.columns == one.columns && two.rows.size() == one.rows.size() && two.rows.size() == 4;
  double largest = 0.0;
  for (const std::string name : {"step", "tether_force", "tether_force_x", "tether_force_y", "pivot_angle_deg"}) {
    const auto it = std::find(two.columns.begin(), two.columns.end(), name);
    same = same && it != two.columns.end();
    const auto k = static_cast<std::size_t>(it - two.columns.begin());
    for (std::size_t r = 0; same && r < two.rows.size(); ++r) {
      same = two.rows[r][k] == one.rows[r][k];
      largest = name == "tether_force" ? std::max(largest, two.rows[r][k]) : largest;
    }
  }
  EXPECT_TRUE(capsula::testing::allRanks(*comm, same));
  EXPECT_TRUE(capsula::testing::allRanks(*comm, largest > 0.0)) << largest; // the tether pulled
  comm->barrier();
  if (comm->getRank() == 0) {
    std::filesystem::remove_all(root);
  }
}

} // namespace
