// Reproducibility: the same seed gives the same bond events whichever receptors a "rank"
// holds and in whichever order they are visited.
#include <capsula/adhesion/AdhesionOutputs.hpp>
#include <capsula/adhesion/BondPopulation.hpp>
#include <capsula/adhesion/Receptors.hpp>
#include <capsula/mesh/Icosphere.hpp>

#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace adhesion = capsula::adhesion;
namespace mesh = capsula::mesh;
using mesh::Vec3;

namespace {

// A cell resting 0.01 above the wall and rolling along x: bonds form under it, stretch as it
// moves and break.
struct RollingCell {
  mesh::SurfaceMesh sphere = mesh::makeIcosphere(2);
  adhesion::ReceptorSet receptors;
  adhesion::AdhesionSettings settings;
  RollingCell() : receptors(sphere, sphere.positions(), 200.0, 99, 1)
  {
    settings.enabled = true;
    settings.reactionDistance = 0.1;
    settings.onRate = 0.5; // k_on0 n_L = 50
    settings.offRate = 2.0;
    settings.springConstant = 10.0;
    settings.reactiveCompliance = 1e-4;
    settings.seed = 31;
  }
  // Positions at step n: translated 0.01 n along x, lowest node at height 0.01.
  std::vector<double> positions(int n) const
  {
    std::vector<double> x = sphere.positions();
    double lowest = 0.0;
    for (std::size_t i = 1; i < x.size(); i += 3) {
      lowest = std::min(lowest, x[i]);
    }
    const double lift = 0.01 - lowest;
    for (std::size_t i = 0; i < x.size(); i += 3) {
      x[i] += 0.01 * n;
      x[i + 1] += lift;
    }
    return x;
  }
};

void expectSameStates(const adhesion::BondPopulation& a, const adhesion::BondPopulation& b)
{
  ASSERT_EQ(a.size(), b.size());
  for (int r = 0; r < a.size(); ++r) {
    // Bit for bit: the same draws and the same arithmetic.
    ASSERT_EQ(a.state(r).occupancy, b.state(r).occupancy) << "receptor " << r;
    ASSERT_EQ(a.state(r).anchor, b.state(r).anchor) << "receptor " << r;
  }
}

} // namespace

TEST(BondPartition, SameSeedSameEventsWhateverThePartitionOrOrder)
{
  const RollingCell cell;
  const int n = cell.receptors.size();
  adhesion::BondPopulation whole(cell.settings, 1, n), reversed(cell.settings, 1, n);
  // Two "ranks", each holding all states but updating only its half of the receptors.
  adhesion::BondPopulation rank0(cell.settings, 1, n), rank1(cell.settings, 1, n);
  const auto half0 = adhesion::ownedReceptors(n, 0, 2), half1 = adhesion::ownedReceptors(n, 1, 2);
  ASSERT_EQ(half0.first, 0);
  ASSERT_EQ(half0.last, half1.first);
  ASSERT_EQ(half1.last, n);
  int formed = 0, broken = 0;
  for (int step = 1; step <= 60; ++step) {
    const std::vector<double> x = cell.positions(step);
    const double dt = 0.02;
    const auto events = whole.update(cell.sphere, cell.receptors, x.data(), dt, step);
    formed += events.formed;
    broken += events.broken;
    for (int r = n - 1; r >= 0; --r) { // one receptor at a time, last first
      reversed.update(cell.sphere, cell.receptors, x.data(), dt, step, r, r + 1);
    }
    rank1.update(cell.sphere, cell.receptors, x.data(), dt, step, half1.first, half1.last);
    rank0.update(cell.sphere, cell.receptors, x.data(), dt, step, half0.first, half0.last);
  }
  // The test means something only if bonds formed, stretched and broke.
  EXPECT_GT(formed, 20);
  EXPECT_GT(broken, 10);
  std::printf("%d receptors, %d bonds formed, %d broken, %g left\n", n, formed, broken, whole.bondCount());
  expectSameStates(whole, reversed);
  // The ranks' halves together are the whole.
  adhesion::BondPopulation joined(cell.settings, 1, n);
  for (int r = 0; r < n; ++r) {
    joined.setState(r, r < half1.first ? rank0.state(r) : rank1.state(r));
  }
  expectSameStates(whole, joined);
  // shareBondStates on one rank keeps every state.
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  if (comm->getSize() == 1) {
    adhesion::shareBondStates(joined, *comm);
    expectSameStates(whole, joined);
  }
  // Another seed gives other events.
  auto otherSettings = cell.settings;
  otherSettings.seed = 32;
  adhesion::BondPopulation other(otherSettings, 1, n);
  for (int step = 1; step <= 60; ++step) {
    const std::vector<double> x = cell.positions(step);
    other.update(cell.sphere, cell.receptors, x.data(), 0.02, step);
  }
  int differ = 0;
  for (int r = 0; r < n; ++r) {
    differ += other.state(r).occupancy != whole.state(r).occupancy ? 1 : 0;
  }
  EXPECT_GT(differ, 0);
}
