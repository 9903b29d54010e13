// The periodic channel's far field (PeriodicFarField.hpp) and its own-cell subtraction
// -s_t . B_t, whose 3x3 blocks B_t are summed once per geometry and set of targets and reused
// by the later applications. Checked against what they replace: the direct sums of the
// subtracted form over the own cell at every application, and an object that has just summed
// its blocks afresh, which a moved geometry or other targets must reproduce bit for bit (a
// block kept from the old geometry differs in every digit that the move changes).
#include <capsula/operators/DirectSummation.hpp>
#include <capsula/operators/RegularSums.hpp>
#include <capsula/periodic/NearestWallKernel.hpp>
#include <capsula/periodic/PeriodicFarField.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace {

using namespace capsula;

constexpr double channelHeight = 2.0;
const periodic::PeriodicBox box{2.0, 2.0};

// Two clusters of source points ("cells"), 40 each, with their area vectors and densities.
struct Sources {
  std::vector<double> x, y, z, ax, ay, az, vx, vy, vz;
  std::vector<int> offsets{0, 40, 80};

  explicit Sources(unsigned seed, double shift = 0.0)
  {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const double centres[2][3] = {{0.5, 0.6, 0.5}, {1.5, 1.3, 1.4}};
    for (const auto& centre : centres) {
      for (int q = 0; q < 40; ++q) {
        x.push_back(centre[0] + shift + 0.3 * unit(random));
        y.push_back(centre[1] + 0.3 * unit(random));
        z.push_back(centre[2] + 0.3 * unit(random));
        for (auto* v : {&ax, &ay, &az}) {
          v->push_back(0.01 * unit(random));
        }
        for (auto* v : {&vx, &vy, &vz}) {
          v->push_back(unit(random));
        }
      }
    }
  }
  operators::DoubleLayerSources view() const
  {
    return {x.data(), y.data(), z.data(), ax.data(), ay.data(), az.data(), vx.data(), vy.data(), vz.data()};
  }
};

// Targets near both clusters, each with its cell and the subtracted density s_t.
struct Targets {
  std::vector<double> points, subtracted;
  std::vector<int> cells;

  explicit Targets(unsigned seed)
  {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int t = 0; t < 12; ++t) {
      const int cell = t < 7 ? 0 : 1;
      const double centre[3] = {cell == 0 ? 0.5 : 1.5, cell == 0 ? 0.6 : 1.3, cell == 0 ? 0.5 : 1.4};
      for (int i = 0; i < 3; ++i) {
        points.push_back(centre[i] + 0.35 * unit(random));
        subtracted.push_back(unit(random));
      }
      cells.push_back(cell);
    }
  }
  int size() const { return static_cast<int>(cells.size()); }
};

periodic::PeriodicFarField channelFarField()
{
  return periodic::PeriodicFarField(box, 1e-8, periodic::PeriodicFluid::Channel, channelHeight);
}

std::vector<double> subtractedDoubleLayer(periodic::PeriodicFarField& farField, const Sources& sources,
                                          const Targets& targets)
{
  std::vector<double> result(targets.points.size());
  farField.doubleLayer(sources.view(), targets.points.data(), targets.cells.data(), targets.subtracted.data(),
                       targets.size(), result.data());
  return result;
}

std::vector<double> freshSubtractedDoubleLayer(const Sources& sources, const Targets& targets)
{
  periodic::PeriodicFarField fresh = channelFarField();
  fresh.setSources(sources.x.data(), sources.y.data(), sources.z.data(), sources.offsets);
  return subtractedDoubleLayer(fresh, sources, targets);
}

} // namespace

TEST(PeriodicFarField, OwnCellSubtractionIsTheDirectSumOverTheOwnCell)
{
  const Sources sources(3);
  const Targets targets(5);
  periodic::PeriodicFarField farField = channelFarField();
  farField.setSources(sources.x.data(), sources.y.data(), sources.z.data(), sources.offsets);
  std::vector<double> plain(targets.points.size());
  farField.doubleLayer(sources.view(), targets.points.data(), nullptr, nullptr, targets.size(), plain.data());
  const std::vector<double> first = subtractedDoubleLayer(farField, sources, targets);
  const std::vector<double> again = subtractedDoubleLayer(farField, sources, targets); // the kept blocks
  EXPECT_EQ(first, again);

  // What the blocks stand for: -sum_{own cell} T_ijk(x_q, x_t) s_t,i a_q,k with the nearer
  // wall's Blake kernel, the direct sums of the subtracted form with zero density.
  const std::vector<double> zero(sources.x.size(), 0.0);
  const operators::DoubleLayerSources own{sources.x.data(),  sources.y.data(),  sources.z.data(),
                                          sources.ax.data(), sources.ay.data(), sources.az.data(),
                                          zero.data(),       zero.data(),       zero.data()};
  std::vector<double> direct(targets.points.size());
  operators::forTargetBlocks(targets.points.data(), targets.cells.data(), targets.subtracted.data(), targets.size(),
                             direct.data(), [&](operators::TargetBlock& block, int cell) {
                               operators::addDoubleLayerSums<periodic::NearestWallKernel, true>(
                                   periodic::NearestWallKernel{channelHeight}, block, own, sources.offsets[cell],
                                   sources.offsets[cell + 1]);
                             });
  double largest = 0.0, error = 0.0;
  for (std::size_t k = 0; k < direct.size(); ++k) {
    largest = std::max(largest, std::abs(direct[k]));
    error = std::max(error, std::abs(first[k] - plain[k] - direct[k]));
  }
  std::printf("own-cell subtraction: largest term %.3e, blocks against the direct sums %.3e\n", largest, error);
  ASSERT_GT(largest, 1e-3); // the targets lie among their cell's points: the term is not negligible
  // Three sums of 40 terms each recombined against one: round-off of the terms' size (1e-16
  // of the largest of them, which the cancellation between near and far points exceeds by
  // up to 1e3). A block of the wrong cell or a transposed block is off by O(largest).
  EXPECT_LT(error, 1e-12 * largest);
}

TEST(PeriodicFarField, OwnCellBlocksFollowTheGeometryAndTheTargets)
{
  const Sources before(3), moved(3, 0.05);
  const Targets targets(5), others(7);
  periodic::PeriodicFarField farField = channelFarField();
  farField.setSources(before.x.data(), before.y.data(), before.z.data(), before.offsets);
  const std::vector<double> old = subtractedDoubleLayer(farField, before, targets);

  farField.setSources(moved.x.data(), moved.y.data(), moved.z.data(), moved.offsets);
  const std::vector<double> afterMove = subtractedDoubleLayer(farField, moved, targets);
  EXPECT_EQ(afterMove, freshSubtractedDoubleLayer(moved, targets));
  EXPECT_NE(afterMove, old);

  EXPECT_EQ(subtractedDoubleLayer(farField, moved, others), freshSubtractedDoubleLayer(moved, others));
  // Back to the first targets on the same geometry: their blocks are summed again, the same.
  EXPECT_EQ(subtractedDoubleLayer(farField, moved, targets), afterMove);
}
