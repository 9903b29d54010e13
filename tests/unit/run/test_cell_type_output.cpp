// The suspension's outputs per cell type (CellTypeOutput.hpp) on arrangements with a known
// answer: the mean height and velocity of each type's cells, its wall-normal distribution,
// the average over the window, and the averages carried across a checkpoint.
#include <capsula/core/Error.hpp>
#include <capsula/domain/Domain.hpp>
#include <capsula/io/Checkpoint.hpp>
#include <capsula/io/Json.hpp>
#include <capsula/run/CellTypeOutput.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace cell_type_output_tests {

namespace domain = capsula::domain;
namespace run = capsula::run;
using capsula::mesh::Vec3;

domain::Domain channel()
{
  domain::DomainShape shape;
  shape.channelHeight = 4.0;
  shape.periodX = 8.0;
  shape.periodZ = 8.0;
  return domain::Domain(shape);
}

// Cells 0, 2 and 3 are red cells at heights 1, 2 and 3; cell 1 a platelet at 0.5; cell 4 has no
// type. Four bins of width 1 over 0 < y < 4.
const std::vector<std::string> kTypes{"red_cell", "platelet", "red_cell", "red_cell", ""};
const std::vector<Vec3> kCentroids{{0.0, 1.5, 0.0}, {3.0, 0.5, 1.0}, {1.0, 2.5, 2.0}, {5.0, 3.5, 0.0}, {0, 2, 0}};
const std::vector<Vec3> kVelocities{{1.0, 0.0, 0.0}, {0.25, 0.1, 0.0}, {2.0, 0.0, 0.0}, {3.0, 0.0, 0.0}, {9, 9, 9}};

TEST(CellTypeOutput, MeansAndDistributionOfEachType)
{
  const auto box = channel();
  run::CellTypeOutput output(kTypes, box, 4, 0.0);
  ASSERT_EQ(output.types(), (std::vector<std::string>{"red_cell", "platelet"}));
  EXPECT_EQ(output.columns(),
            (std::vector<std::string>{"y_mean_red_cell", "u_mean_red_cell", "y_mean_platelet", "u_mean_platelet"}));
  const auto sample = output.measure(0.0, kCentroids, kVelocities);
  // Exact sums of a few binary fractions: 2.5 = (1.5 + 2.5 + 3.5) / 3, 2 = (1 + 2 + 3) / 3.
  EXPECT_EQ(output.row(sample), (std::vector<double>{2.5, 2.0, 0.5, 0.25}));
  // One red cell in each of the bins 1-3 (density 1/3 per unit height), the platelet in bin 0.
  ASSERT_EQ(sample.density.size(), 2u);
  EXPECT_EQ(sample.density[0], (std::vector<double>{0.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0}));
  EXPECT_EQ(sample.density[1], (std::vector<double>{1.0, 0.0, 0.0, 0.0}));
  const auto blocks = output.blocks(sample);
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[1].name, "height_platelet");
  EXPECT_EQ(blocks[1].positions[1], 0.5); // the first bin's centre
}

// Outputs at t = 0 (before the window), 1 and 2; the platelet at 0.5, then 1.5: the average
// of the window is its mean, and a checkpoint taken after t = 1 continues it exactly.
TEST(CellTypeOutput, AveragesTheWindowAcrossACheckpoint)
{
  const auto box = channel();
  auto at = [](double platelet) {
    std::vector<Vec3> centroids = kCentroids;
    centroids[1][1] = platelet;
    return centroids;
  };
  run::CellTypeOutput whole(kTypes, box, 4, 0.5);
  whole.measure(0.0, at(3.5), kVelocities);
  whole.measure(1.0, at(0.5), kVelocities);
  capsula::io::Checkpoint checkpoint;
  whole.save(checkpoint);
  whole.measure(2.0, at(1.5), kVelocities);

  run::CellTypeOutput resumed(kTypes, box, 4, 0.5);
  resumed.load(checkpoint, "test");
  resumed.measure(2.0, at(1.5), kVelocities);

  capsula::io::JsonValue a, b;
  whole.addResults(a);
  resumed.addResults(b);
  EXPECT_EQ(capsula::io::toJson(a), capsula::io::toJson(b));
  auto& platelet = a["cell types"]["platelet"];
  EXPECT_EQ(platelet["outputs averaged"].asInteger(), 2);
  EXPECT_EQ(platelet["y_mean"].asNumber(), 1.0);
  EXPECT_EQ(capsula::io::toJson(platelet["height distribution"]["values"], 0), "[0.5,0.5,0.0,0.0]");
  // A checkpoint of a run without the types is refused.
  run::CellTypeOutput fresh(kTypes, box, 4, 0.5);
  EXPECT_THROW(fresh.load(capsula::io::Checkpoint{}, "old"), capsula::core::IoError);
}

} // namespace cell_type_output_tests
