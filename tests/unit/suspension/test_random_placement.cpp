// Random sequential placement (RandomPlacement.hpp): the cells it places are clear of each
// other, of their periodic images and of both walls by the gaps asked for; the same seed
// gives the same cells; the deck's keys rebuild each cell; a packing that jams and a
// hematocrit the box cannot resolve are refused.
#include "SuspensionTesting.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/domain/Domain.hpp>
#include <capsula/mesh/Placement.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/scene/CellPlacement.hpp>
#include <capsula/suspension/RandomPlacement.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace {

namespace domain = capsula::domain;
namespace mesh = capsula::mesh;
namespace scene = capsula::scene;
namespace suspension = capsula::suspension;
using mesh::Vec3;

domain::Domain box(double lx, double height, double lz)
{
  return capsula::suspension::testing::periodicChannel(lx, height, lz);
}

// Red-cell-sized spheroids (radius 1, half-thickness 0.4) and platelet-sized ones (0.4, 0.1).
std::vector<suspension::CellType> redCellsAndPlatelets(int reds, int platelets)
{
  return {{"platelet", mesh::makeSpheroid(1, 0.4, 0.1), platelets},
          {"red cell", mesh::makeSpheroid(1, 1.0, 0.4), reds}};
}

TEST(RandomPlacement, CellsKeepTheirGapsFromEachOtherTheirImagesAndTheWalls)
{
  const auto channel = box(7.0, 4.0, 6.0);
  suspension::PlacementSettings settings;
  settings.seed = 7;
  settings.minimumCellGap = 0.05;
  settings.minimumWallGap = 0.1;
  const auto cells = suspension::placeCells(redCellsAndPlatelets(8, 10), channel, settings);
  ASSERT_EQ(cells.size(), 18u);
  // The red cells come first (largest types first), then the platelets.
  EXPECT_EQ(cells.front().type, 1);
  EXPECT_EQ(cells.back().type, 0);
  std::vector<const mesh::SurfaceMesh*> surfaces;
  std::vector<std::string> paths;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    surfaces.push_back(&cells[c].surface);
    paths.push_back("Cells/Cell " + std::to_string(c));
    EXPECT_NO_THROW(scene::requireWallGaps(cells[c].surface, paths.back(), channel, 0.1));
    EXPECT_NO_THROW(scene::requireRoomInDomain(cells[c].surface, paths.back(), channel, 0.1, 0.05));
    EXPECT_GE(cells[c].centre[0], 0.0);
    EXPECT_LT(cells[c].centre[0], 7.0);
  }
  // The start-up check of the scene, with the periodic images, accepts the arrangement.
  EXPECT_NO_THROW(scene::requireNoOverlap(surfaces, paths, 0.05, channel));
}

TEST(RandomPlacement, TheSameSeedGivesTheSameCells)
{
  const auto channel = box(6.0, 4.0, 6.0);
  suspension::PlacementSettings settings;
  settings.seed = 11;
  const auto first = suspension::placeCells(redCellsAndPlatelets(5, 4), channel, settings);
  const auto again = suspension::placeCells(redCellsAndPlatelets(5, 4), channel, settings);
  settings.seed = 12;
  const auto other = suspension::placeCells(redCellsAndPlatelets(5, 4), channel, settings);
  ASSERT_EQ(first.size(), again.size());
  double moved = 0.0;
  for (std::size_t c = 0; c < first.size(); ++c) {
    EXPECT_EQ(first[c].centre, again[c].centre);
    EXPECT_EQ(first[c].angleDegrees, again[c].angleDegrees);
    moved = std::max(moved, (first[c].centre - other[c].centre).norm());
  }
  EXPECT_GT(moved, 0.1);
}

// A placed cell is what its deck keys build: the body shape rotated by 'Orientation angle'
// degrees about 'Orientation axis' and moved to 'Center' (mesh/CellSurfaceParameters.cpp).
TEST(RandomPlacement, DeckKeysRebuildEachCell)
{
  const auto channel = box(6.0, 4.0, 6.0);
  const auto cells = suspension::placeCells(redCellsAndPlatelets(3, 0), channel, {});
  for (const auto& cell : cells) {
    mesh::Placement placement;
    placement.centre = cell.centre;
    placement.rotation = mesh::rotationAboutAxis(cell.axis, cell.angleDegrees * M_PI / 180.0);
    const auto rebuilt = mesh::makeSpheroid(1, 1.0, 0.4, placement);
    for (int i = 0; i < rebuilt.numNodes(); ++i) {
      EXPECT_LT((rebuilt.position(i) - cell.surface.position(i)).norm(), 1e-12);
    }
  }
}

TEST(RandomPlacement, AJammedPackingIsRefused)
{
  suspension::PlacementSettings settings;
  settings.attempts = 300;
  try {
    // 12 spheroids of volume 1.68 in a box of 36: a volume fraction of 0.56, past jamming.
    suspension::placeCells(redCellsAndPlatelets(12, 0), box(4.0, 3.0, 3.0), settings);
    FAIL() << "an impossible packing was placed";
  } catch (const capsula::core::InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("The suspension jams"), std::string::npos) << what;
    EXPECT_NE(what.find("of type 'red cell'"), std::string::npos) << what;
  }
  EXPECT_THROW(suspension::placeCells(redCellsAndPlatelets(1, 0), domain::Domain::channel(4.0), settings),
               capsula::core::InputError);
}

// Box 10 x 10 x 10, a cell of volume 4 pi / 3: 0.1 is 23.87 cells, 24 give 0.10053 (0.5%
// off, accepted); 0.0115 is 2.75 cells, 3 give 0.01257 (9% off, refused).
TEST(RandomPlacement, HematocritWithinOnePercent)
{
  const auto channel = box(10.0, 10.0, 10.0);
  const double volume = 4.0 * M_PI / 3.0;
  EXPECT_EQ(suspension::cellsForHematocrit(0.1, volume, channel), 24);
  try {
    suspension::cellsForHematocrit(0.0115, volume, channel);
    FAIL() << "a hematocrit the box cannot resolve was accepted";
  } catch (const capsula::core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'Suspension/Hematocrit' = 0.0115 cannot be met within 1%"), std::string::npos)
        << e.what();
  }
}

} // namespace
