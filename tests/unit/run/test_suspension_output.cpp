// The suspension's outputs of a scene run ('Output/Suspension', SuspensionOutput.hpp): the
// hematocrit profile against the cells' volume over the box, the cell-free layer against the
// nearest membrane node, the time average over its window and across a checkpoint, the
// refusals of a box the deck leaves open; then a run of two cells above the wall, its files
// checked against its own snapshots, and its restart against the uninterrupted run.
#include "SceneRunFixture.hpp"

#include <capsula/core/Deck.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/io/Checkpoint.hpp>
#include <capsula/io/Json.hpp>
#include <capsula/io/MetricsCsv.hpp>
#include <capsula/io/SnapshotFile.hpp>
#include <capsula/mesh/Placement.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/run/RelativeViscosity.hpp>
#include <capsula/run/SuspensionOutput.hpp>
#include <capsula/suspension/FlatFacets.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace suspension_output_test { // the file's own names, apart from those of the files compiled with it
namespace {

namespace core = capsula::core;
namespace domain = capsula::domain;
namespace io = capsula::io;
namespace mesh = capsula::mesh;
namespace run = capsula::run;
namespace suspension = capsula::suspension;
using mesh::Vec3;

mesh::SurfaceMesh sphereAt(const Vec3& centre)
{
  mesh::Placement placement;
  placement.centre = centre;
  return mesh::makeSphere(1, 1.0, placement);
}

std::vector<const mesh::SurfaceMesh*> pointers(const std::vector<mesh::SurfaceMesh>& cells)
{
  std::vector<const mesh::SurfaceMesh*> out;
  for (const auto& cell : cells) {
    out.push_back(&cell);
  }
  return out;
}

// The flat-faceted volume of 6-node triangles (`connectivity`, 6 per element) at `positions`
// as signed tetrahedra from the origin, p0 . (p1 x p2) / 6: another formula than the slab
// volumes' x n_x flux through clipped facets.
double tetrahedraVolume(const std::vector<double>& positions, const std::vector<std::int64_t>& connectivity)
{
  double volume = 0.0;
  for (std::size_t e = 0; e + 6 <= connectivity.size(); e += 6) {
    for (const auto& piece : suspension::flatFacetPieces) {
      Vec3 p[3];
      for (int i = 0; i < 3; ++i) {
        const auto node = static_cast<std::size_t>(connectivity[e + static_cast<std::size_t>(piece[i])]);
        p[i] = Vec3(positions[3 * node], positions[3 * node + 1], positions[3 * node + 2]);
      }
      volume += p[0].dot(p[1].cross(p[2])) / 6.0;
    }
  }
  return volume;
}

double tetrahedraVolume(const mesh::SurfaceMesh& cell)
{
  std::vector<double> positions(cell.positionData(), cell.positionData() + 3 * cell.numNodes());
  std::vector<std::int64_t> connectivity;
  for (int e = 0; e < cell.numElements(); ++e) {
    for (int node : cell.element(e)) {
      connectivity.push_back(node);
    }
  }
  return tetrahedraVolume(positions, connectivity);
}

// The settings as read from a declared "Suspension" sublist with `tweak` applied.
template <typename Tweak>
run::SuspensionOutputSettings settingsFor(const domain::Domain& domain, Tweak&& tweak)
{
  Teuchos::ParameterList list("Suspension");
  run::declareSuspensionOutputParameters(list);
  list.set("Enabled", true);
  tweak(list);
  return run::readSuspensionOutputSettings(list, domain);
}

// The box 0 < y < 5 over 7 x 9 above the wall, in 10 slabs.
run::SuspensionOutputSettings wallBox(double averageFrom = 0.0)
{
  return settingsFor(domain::Domain::aboveWall(), [&](Teuchos::ParameterList& list) {
    list.set("Height", 5.0);
    list.set("Box length x", 7.0);
    list.set("Box length z", 9.0);
    list.set("Bins", 10);
    list.set("Average from", averageFrom);
  });
}

// Summed over the slabs, fraction times slab volume is the cells' flat-faceted volume: the
// slab volumes are exact for the flat facets, so only round-off separates them (1e-12 of the
// volume); a wrong slab volume (area, thickness or bin count) is off by O(1).
TEST(SuspensionOutput, ProfileIntegratesToTheCellsVolumeOverTheBox)
{
  const domain::Domain wall = domain::Domain::aboveWall();
  run::SuspensionOutput output(wallBox(), wall);
  const std::vector<mesh::SurfaceMesh> cells{sphereAt({0.0, 1.6, 0.0}), sphereAt({2.5, 3.1, 0.5}),
                                             sphereAt({-4.0, 2.2, 12.0})}; // x, z outside the box: counted
  const run::SuspensionSample sample = output.measure(0.0, pointers(cells));
  ASSERT_EQ(sample.profile.fraction.size(), 10u);
  const double slabVolume = 7.0 * 9.0 * 5.0 / 10.0;
  double integral = 0.0;
  for (double f : sample.profile.fraction) {
    EXPECT_GE(f, 0.0);
    integral += f * slabVolume;
  }
  double volume = 0.0;
  for (const auto& cell : cells) {
    volume += tetrahedraVolume(cell);
  }
  EXPECT_NEAR(integral, volume, 1e-12 * volume);
  // The slab 0 < y < 0.5 lies below every cell (lowest at y = 0.6).
  EXPECT_EQ(sample.profile.fraction.front(), 0.0);
  // The bin centres are those of the polyline written to suspension.h5.
  const io::SnapshotBlock block = output.profileBlock(sample);
  EXPECT_EQ(block.nodeFields.front().values, sample.profile.fraction);
  EXPECT_DOUBLE_EQ(block.positions[1], 0.25);
  EXPECT_DOUBLE_EQ(block.positions[3 * 9 + 1], 4.75);
}

// Without a periodic box the layer is the distance from each wall to the nearest membrane
// node, found here node by node through the domain's own wall distances.
TEST(SuspensionOutput, CellFreeLayerIsTheNearestNodesWallDistance)
{
  const domain::Domain channel = domain::Domain::channel(6.0);
  run::SuspensionOutput output(settingsFor(channel,
                                           [](Teuchos::ParameterList& list) {
                                             list.set("Box length x", 7.0);
                                             list.set("Box length z", 9.0);
                                           }),
                               channel);
  EXPECT_EQ(output.columns(), (std::vector<std::string>{"cell_free_layer_lower", "cell_free_layer_upper"}));
  const std::vector<mesh::SurfaceMesh> cells{sphereAt({0.0, 1.7, 0.0}), sphereAt({2.5, 4.2, 0.5})};
  double lower = std::numeric_limits<double>::infinity(), upper = lower;
  for (const auto& cell : cells) {
    for (int n = 0; n < cell.numNodes(); ++n) {
      const Vec3 x = mesh::nodeAt(cell.positionData(), n);
      const double point[3] = {x[0], x[1], x[2]};
      int nearest = -1;
      const double distance = channel.distanceToNearestWall(point, &nearest);
      (nearest == 0 ? lower : upper) = std::min(nearest == 0 ? lower : upper, distance);
    }
  }
  const std::vector<double> row = output.row(output.measure(0.0, pointers(cells)));
  ASSERT_EQ(row.size(), 2u);
  EXPECT_NEAR(row[0], lower, 1e-14); // the same node: only the subtraction H - y may round
  EXPECT_NEAR(row[1], upper, 1e-14);
  // The nodes lie on the unit spheres: the lowest 0.7 above the wall at most.
  EXPECT_GT(row[0], 0.7 - 1e-12);
  EXPECT_LT(row[0], 0.8);
  EXPECT_GT(row[1], 0.8 - 1e-12);
  EXPECT_LT(row[1], 0.9);
}

// The channel 0 < y < 6 periodic along x and z with periods 5.
domain::Domain periodicChannel()
{
  domain::DomainShape shape;
  shape.channelHeight = 6.0;
  shape.periodX = 5.0;
  shape.periodZ = 5.0;
  return domain::Domain(shape);
}

// In a channel periodic along x and z the layer is the suspension package's column mean,
// which for one sphere is larger than its thinnest point (most columns count H / 2).
TEST(SuspensionOutput, PeriodicChannelTakesTheColumnMean)
{
  const domain::Domain box = periodicChannel();
  run::SuspensionOutput output(settingsFor(box, [](Teuchos::ParameterList& list) { list.set("Columns", 16); }), box);
  const std::vector<mesh::SurfaceMesh> cells{sphereAt({1.0, 1.7, 2.0})};
  EXPECT_EQ(output.columns(),
            (std::vector<std::string>{"cell_free_layer_lower", "cell_free_layer_upper", "relative_viscosity"}));
  const std::vector<double> row = output.row(output.measure(0.0, pointers(cells), 1.25));
  const suspension::CellFreeLayer columns = suspension::cellFreeLayer(pointers(cells), box, 16, 16);
  EXPECT_EQ(row[0], columns.lower);
  EXPECT_EQ(row[1], columns.upper);
  EXPECT_EQ(row[2], 1.25);      // the relative viscosity the caller measured
  EXPECT_GT(row[0], 0.7 + 0.5); // the thinnest point is 0.7; the mean is well above
}

// The relative viscosity's mean over the window goes to summary.json and its running sum
// through a checkpoint; a checkpoint without the sum is refused, naming it.
TEST(SuspensionOutput, RelativeViscosityAverageContinuesAcrossACheckpoint)
{
  const domain::Domain box = periodicChannel();
  const run::SuspensionOutputSettings settings =
      settingsFor(box, [](Teuchos::ParameterList& list) { list.set("Average from", 1.0); });
  const std::vector<mesh::SurfaceMesh> cells{sphereAt({1.0, 1.7, 2.0})};
  run::SuspensionOutput whole(settings, box);
  whole.measure(0.0, pointers(cells), 9.0); // before the window
  whole.measure(1.0, pointers(cells), 1.5);
  io::Checkpoint checkpoint;
  whole.save(checkpoint);
  whole.measure(2.0, pointers(cells), 1.75);
  io::JsonValue summary;
  whole.addResults(summary);
  EXPECT_EQ(summary["relative viscosity"]["value"].asNumber(), 1.625);
  EXPECT_EQ(summary["relative viscosity"]["outputs averaged"].asInteger(), 2);

  run::SuspensionOutput restarted(settings, box);
  restarted.load(checkpoint, "memory");
  restarted.measure(2.0, pointers(cells), 1.75);
  io::JsonValue resumed;
  restarted.addResults(resumed);
  EXPECT_EQ(resumed["relative viscosity"]["value"].asNumber(), 1.625);

  checkpoint.reals.erase("suspension.relative viscosity sum");
  run::SuspensionOutput old(settings, box);
  try {
    old.load(checkpoint, "old.h5");
    ADD_FAILURE() << "a checkpoint without the relative viscosity's sum was read";
  } catch (const core::IoError& e) {
    EXPECT_NE(std::string(e.what()).find("'suspension.relative viscosity sum'"), std::string::npos) << e.what();
  }
}

// A pulsatile flow passes through rest: at k(t) = 0 the relative viscosity is undefined (NaN
// in the output's row). Summed into the window's mean it made the mean NaN for the rest of the
// run; it stays out of it, and the count of outputs it averages says so, across a checkpoint.
TEST(SuspensionOutput, RelativeViscosityAverageSkipsAnInstantAtRest)
{
  const domain::Domain box = periodicChannel();
  const std::vector<mesh::SurfaceMesh> cells{sphereAt({1.0, 1.7, 2.0})};
  const capsula::operators::CellSurfaces surfaces(cells, 1.0);
  const auto load = capsula::operators::LoadDensity::constantOverElements(
      std::vector<double>(3 * static_cast<std::size_t>(surfaces.cell(0).numElements()), 0.0));
  for (const auto kind : {domain::FlowProfileKind::Poiseuille, domain::FlowProfileKind::Shear}) {
    const domain::FlowProfile profile(kind, box);
    EXPECT_TRUE(std::isnan(run::relativeViscosity(surfaces, load, nullptr, 0.1, box, profile, 0.0)));
    // An unloaded cell at lambda = 1 does not disturb the flow: exactly 1 at any k(t) != 0.
    EXPECT_EQ(run::relativeViscosity(surfaces, load, nullptr, 0.1, box, profile, -0.5), 1.0);
  }

  const run::SuspensionOutputSettings settings = settingsFor(box, [](Teuchos::ParameterList&) {});
  run::SuspensionOutput output(settings, box);
  output.measure(0.0, pointers(cells), 1.5);
  output.measure(1.0, pointers(cells), std::numeric_limits<double>::quiet_NaN());
  io::Checkpoint checkpoint;
  output.save(checkpoint);
  run::SuspensionOutput restarted(settings, box);
  restarted.load(checkpoint, "memory");
  for (run::SuspensionOutput* o : {&output, &restarted}) {
    o->measure(2.0, pointers(cells), 1.75);
    io::JsonValue summary;
    o->addResults(summary);
    EXPECT_EQ(summary["relative viscosity"]["value"].asNumber(), 1.625);
    EXPECT_EQ(summary["relative viscosity"]["outputs averaged"].asInteger(), 2);
    EXPECT_EQ(summary["hematocrit"]["outputs averaged"].asInteger(), 3); // the profile has all three
  }
}

// The average is the mean of the profiles at the outputs in the window; a run restarted from
// a checkpoint (written to and read from HDF5) continues it bit for bit.
TEST(SuspensionOutput, AverageCoversTheWindowAndContinuesAcrossACheckpoint)
{
  const domain::Domain wall = domain::Domain::aboveWall();
  std::vector<mesh::SurfaceMesh> cells{sphereAt({0.0, 1.6, 0.0}), sphereAt({2.5, 3.1, 0.5})};
  const auto moved = [&](double dy) {
    std::vector<mesh::SurfaceMesh> out;
    for (const auto& cell : cells) {
      mesh::SurfaceMesh copy = cell;
      mesh::Placement shift;
      shift.centre = Vec3(0.0, dy, 0.0);
      mesh::applyPlacement(copy, shift);
      out.push_back(copy);
    }
    return out;
  };
  const auto before = moved(0.0), first = moved(0.3), second = moved(0.7);

  run::SuspensionOutput whole(wallBox(0.5), wall);
  whole.measure(0.0, pointers(before)); // before the window
  const auto p1 = whole.measure(0.5, pointers(first)).profile.fraction;
  EXPECT_EQ(whole.averagedOutputs(), 1);
  io::Checkpoint checkpoint;
  whole.save(checkpoint);
  const auto p2 = whole.measure(1.0, pointers(second)).profile.fraction;
  EXPECT_EQ(whole.averagedOutputs(), 2);
  const std::vector<double> average = whole.averageProfile();
  ASSERT_EQ(average.size(), p1.size());
  for (std::size_t k = 0; k < average.size(); ++k) {
    EXPECT_EQ(average[k], (p1[k] + p2[k]) / 2.0); // the same sums in the same order
  }
  EXPECT_NE(p1, p2); // the cells moved across the slabs: the mean is not either profile

  const std::string path = ::testing::TempDir() + "suspension-checkpoint.h5";
  io::writeCheckpoint(path, checkpoint);
  run::SuspensionOutput restarted(wallBox(0.5), wall);
  restarted.load(io::readCheckpoint(path), path);
  restarted.measure(1.0, pointers(second));
  EXPECT_EQ(restarted.averageProfile(), average);
  EXPECT_EQ(restarted.averagedOutputs(), 2);
  std::remove(path.c_str());
}

std::string refusal(const domain::Domain& domain, const std::function<void(Teuchos::ParameterList&)>& tweak)
{
  try {
    settingsFor(domain, tweak);
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SuspensionOutput, RefusesABoxTheDeckLeavesOpen)
{
  const domain::Domain wall = domain::Domain::aboveWall();
  const auto lengths = [](Teuchos::ParameterList& list) {
    list.set("Box length x", 7.0);
    list.set("Box length z", 9.0);
  };
  EXPECT_NE(refusal(wall, lengths).find("'Output/Suspension/Height' = 0"), std::string::npos) << refusal(wall, lengths);
  const std::string noZ = refusal(wall, [](Teuchos::ParameterList& list) {
    list.set("Height", 4.0);
    list.set("Box length x", 7.0);
  });
  EXPECT_NE(noZ.find("'Output/Suspension/Box length z' = 0"), std::string::npos) << noZ;
  const std::string overChannel = refusal(domain::Domain::channel(6.0), [&](Teuchos::ParameterList& list) {
    lengths(list);
    list.set("Height", 4.0);
  });
  EXPECT_NE(overChannel.find("'Output/Suspension/Height' = 4"), std::string::npos) << overChannel;
  EXPECT_NE(overChannel.find("'Wall/Channel height' = 6"), std::string::npos) << overChannel;
  const std::string noWall = refusal(domain::Domain::unbounded(), lengths);
  EXPECT_NE(noWall.find("'Wall/Enabled' is false"), std::string::npos) << noWall;
  // Given fully, the box is accepted; disabled, nothing is checked.
  EXPECT_EQ(refusal(wall,
                    [&](Teuchos::ParameterList& list) {
                      lengths(list);
                      list.set("Height", 4.0);
                    }),
            "");
  EXPECT_EQ(refusal(wall, [](Teuchos::ParameterList& list) { list.set("Enabled", false); }), "");
}

// Two level-1 spheres above the wall, RK4 steps of 0.02 to t = 0.1, outputs every 0.05.
Teuchos::RCP<Teuchos::ParameterList> suspensionDeck(double endTime)
{
  return run::testing::smallDeck(1, 1.6, true, [&](Teuchos::ParameterList& d) {
    auto& second = d.sublist("Cells").sublist("Cell 1");
    second.set("Center", capsula::scene::testing::realArray({3.0, 2.4, 0.5}));
    second.set("Mesh level", 1);
    auto& time = d.sublist("Time integration");
    time.set("Method", std::string("RK4"));
    time.set("Initial step", 0.02);
    time.set("End time", endTime);
    auto& output = d.sublist("Output");
    output.set("Interval", 0.05);
    auto& measured = output.sublist("Suspension");
    measured.set("Enabled", true);
    measured.set("Height", 4.0);
    measured.set("Box length x", 6.0);
    measured.set("Box length z", 6.0);
    measured.set("Bins", 8);
    measured.set("Average from", 0.05);
  });
}

// The text of summary.json's "values" array under "hematocrit", without white space.
std::string hematocritValues(const std::string& summary)
{
  const std::size_t start = summary.find("\"values\"", summary.find("\"hematocrit\""));
  if (start == std::string::npos) {
    return "";
  }
  std::string text = summary.substr(start, summary.find(']', start) - start + 1);
  text.erase(std::remove_if(text.begin(), text.end(), [](char c) { return std::isspace(c) != 0; }), text.end());
  return text;
}

class SuspensionRunTest : public run::testing::SceneRunFixture {};

// The run's files against its own snapshots: at every output the layer is the lowest node's
// height, the profile integrates to the cells' flat-faceted volume over the 6 x 4 x 6 box,
// and summary.json holds the mean of the profiles at t >= 0.05. A restart continues all of it
// bit for bit.
TEST_F(SuspensionRunTest, OutputsMatchTheSnapshotsAndSurviveARestart)
{
  const auto deck = suspensionDeck(0.1);
  const auto result = run(*deck, "whole");
  ASSERT_EQ(result.status, "finished");
  EXPECT_NE(std::find_if(result.terms.begin(), result.terms.end(),
                         [](const std::string& t) { return t.find("output: suspension") == 0; }),
            result.terms.end());
  const io::CsvTable table = io::readCsvTable((root_ / "whole" / "metrics.csv").string());
  const auto column = std::find(table.columns.begin(), table.columns.end(), "cell_free_layer_lower");
  ASSERT_NE(column, table.columns.end());
  EXPECT_EQ(std::find(table.columns.begin(), table.columns.end(), "cell_free_layer_upper"), table.columns.end());
  const auto layerColumn = static_cast<std::size_t>(column - table.columns.begin());

  const std::string cellsFile = (root_ / "whole" / "snapshots.h5").string();
  const std::string profileFile = (root_ / "whole" / "suspension.h5").string();
  const std::size_t outputs = io::readSnapshotLayouts(profileFile).size();
  ASSERT_EQ(outputs, 3u); // t = 0, 0.05, 0.1
  ASSERT_EQ(table.rows.size(), outputs);
  std::vector<double> sum(8, 0.0);
  for (std::size_t k = 0; k < outputs; ++k) {
    const io::Snapshot cells = io::readSnapshot(cellsFile, k);
    const io::Snapshot profile = io::readSnapshot(profileFile, k);
    EXPECT_EQ(profile.time, cells.time);
    double lowest = std::numeric_limits<double>::infinity(), volume = 0.0;
    for (const auto& block : cells.blocks) {
      for (std::size_t n = 1; n < block.positions.size(); n += 3) {
        lowest = std::min(lowest, block.positions[n]);
      }
      volume += tetrahedraVolume(block.positions, block.connectivity);
    }
    // metrics.csv writes round-trip digits of the same double.
    EXPECT_EQ(table.rows[k][layerColumn], lowest) << "output " << k;
    const std::vector<double>& fraction = profile.blocks.at(0).nodeFields.at(0).values;
    ASSERT_EQ(fraction.size(), 8u);
    double integral = 0.0;
    for (double f : fraction) {
      integral += f * 6.0 * 6.0 * 4.0 / 8.0;
    }
    EXPECT_NEAR(integral, volume, 1e-12 * volume) << "output " << k; // exact up to round-off
    if (k >= 1) {                                                    // t >= 0.05
      for (std::size_t b = 0; b < 8; ++b) {
        sum[b] += fraction[b];
      }
    }
  }
  for (double& s : sum) {
    s /= 2.0;
  }
  const std::string expected =
      hematocritValues("{\"hematocrit\": {\"values\": " + io::toJson(io::JsonValue::array(sum)) + "}}");
  EXPECT_EQ(hematocritValues(read("whole/summary.json")), expected);

  run(*suspensionDeck(0.05), "split");
  EXPECT_EQ(run(*deck, "split", "split").status, "finished");
  EXPECT_EQ(read("split/metrics.csv"), read("whole/metrics.csv"));
  EXPECT_EQ(hematocritValues(read("split/summary.json")), expected);
  const std::string splitProfiles = (root_ / "split" / "suspension.h5").string();
  ASSERT_EQ(io::readSnapshotLayouts(splitProfiles).size(), outputs);
  for (std::size_t k = 0; k < outputs; ++k) {
    EXPECT_EQ(io::readSnapshot(splitProfiles, k).blocks.at(0).nodeFields.at(0).values,
              io::readSnapshot(profileFile, k).blocks.at(0).nodeFields.at(0).values);
  }
}

} // namespace

} // namespace suspension_output_test
