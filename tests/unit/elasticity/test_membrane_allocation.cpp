// MembraneMechanics::evaluate and HelfrichBending::evaluate run every right-hand-side
// evaluation, and HelfrichBending::applyStiffness every Krylov iteration: they must not
// touch the heap. This executable counts calls to the global operator new.
#include "MembraneTesting.hpp"

#include <capsula/elasticity/HelfrichBending.hpp>
#include <capsula/elasticity/MembraneMechanics.hpp>
#include <capsula/elasticity/SkalakLaw.hpp>
#include <capsula/mesh/Shapes.hpp>

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

namespace {
std::atomic<long> allocations{0};
} // namespace

void* operator new(std::size_t size)
{
  ++allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) {
    return p;
  }
  throw std::bad_alloc();
}
// Out of line: inlined next to a test's `new`, the free() inside looks to GCC's
// -Wmismatched-new-delete like the wrong deallocation for it.
[[gnu::noinline]] void operator delete(void* p) noexcept
{
  std::free(p);
}
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept
{
  std::free(p);
}

TEST(MembraneAllocation, EvaluateDoesNotAllocate)
{
  using namespace capsula::elasticity;
  const capsula::mesh::SurfaceMesh mesh = capsula::mesh::makeSphere(2, 1.0);
  const auto current =
      capsula::elasticity::testing::mapNodes(mesh.positions(), capsula::elasticity::testing::smoothDeformation);
  MembraneMechanics m(mesh, mesh.positions(), std::make_shared<SkalakLaw>(1.0, 10.0));
  const long before = allocations.load();
  m.evaluate(current.data());
  m.evaluate(mesh.positionData());
  const long during = allocations.load() - before;
  EXPECT_EQ(during, 0);
  // The counter works: building an object does allocate.
  const long again = allocations.load();
  const MembraneMechanics other(mesh, mesh.positions(), std::make_shared<SkalakLaw>(1.0, 1.0));
  EXPECT_GT(allocations.load() - again, 0);
}

TEST(MembraneAllocation, BendingEvaluateDoesNotAllocate)
{
  using namespace capsula::elasticity;
  const capsula::mesh::SurfaceMesh mesh = capsula::mesh::makeSphere(2, 1.0);
  const auto current =
      capsula::elasticity::testing::mapNodes(mesh.positions(), capsula::elasticity::testing::smoothDeformation);
  HelfrichBending b(mesh, mesh.positions(), BendingParameters{0.5, 0.3, BendingReference::Flat});
  std::vector<double> y(current.size());
  const long before = allocations.load();
  b.evaluate(current.data());
  b.evaluate(mesh.positionData());
  b.applyStiffness(current.data(), y.data());
  EXPECT_EQ(allocations.load() - before, 0);
}
