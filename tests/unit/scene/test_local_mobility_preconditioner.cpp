// The local-mobility preconditioner of the stiff stage solves: P^-1 x solves
// (B^-1 + shift H) z = B^-1 x with H the membrane's stiffness plus the stiffness of the
// forces from outside, whatever pattern those give.
#include <capsula/scene/LocalMobilityPreconditioner.hpp>

#include <capsula/mesh/Icosphere.hpp>

#include <Eigen/Dense>
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace adhesion = capsula::adhesion;
namespace elasticity = capsula::elasticity;
namespace mesh = capsula::mesh;
namespace scene = capsula::scene;

namespace {

// Couples node a to node b (and each to itself) with a 3 x 3 spring of stiffness k: what a
// bond spread over a patch that reaches both adds.
void addSpring(adhesion::LoadStiffness& K, int a, int b, double k)
{
  for (int i = 0; i < 3; ++i) {
    K.add(3 * a + i, 3 * a + i, k);
    K.add(3 * b + i, 3 * b + i, k);
    K.add(3 * a + i, 3 * b + i, -k);
    K.add(3 * b + i, 3 * a + i, -k);
  }
}

} // namespace

// Fixed bug: the symbolic analysis of the factorisation was kept whenever the assembled H had
// as many entries as before. Bonds on patches that form and break between steps change the
// pattern, sometimes keeping that count; the stale analysis then factorised the wrong matrix
// (a run crashed with heap corruption). Two couplings of far nodes, each adding the same
// number of entries, one after the other: each solve must match a dense solve to 1e-10
// (round-off of a well-conditioned 126 x 126 system).
TEST(LocalMobilityPreconditioner, SolvesAfterThePatternChangesAtTheSameSize)
{
  const mesh::SurfaceMesh sphere = mesh::makeIcosphere(1); // 42 nodes, 80 elements
  const int n = 3 * sphere.numNodes();
  std::vector<elasticity::ElementStiffness> elements(static_cast<std::size_t>(sphere.numElements()));
  for (auto& K : elements) { // each element a set of springs along the coordinates: symmetric, >= 0
    K.fill(0.0);
    for (int k = 0; k < 6; ++k) {
      for (int l = 0; l < 6; ++l) {
        for (int i = 0; i < 3; ++i) {
          K[static_cast<std::size_t>((3 * k + i) * 18 + 3 * l + i)] = (k == l ? 5.0 : -1.0);
        }
      }
    }
  }
  const elasticity::TangentStiffness H(sphere, elements);
  const std::vector<double> mobility(static_cast<std::size_t>(sphere.numNodes()), 0.7);
  const auto comm = Tpetra::getDefaultComm();
  auto map = Teuchos::rcp(new Tpetra::Map<>(n, 0, comm, Tpetra::LocallyReplicated));
  scene::LocalMobilityPreconditioner P(map, scene::CellOwnership(comm, {sphere.numNodes()}), {0, sphere.numNodes()});
  const double shift = 0.3;
  // Node 0 coupled to the node farthest from it, then to the next farthest: neither pair
  // shares an element, so each adds the same six entries outside the elements' pattern.
  int farthest = 1, next = 2;
  const auto from0 = [&](int k) { return (sphere.position(k) - sphere.position(0)).norm(); };
  for (int k = 1; k < sphere.numNodes(); ++k) {
    if (from0(k) > from0(farthest)) {
      next = farthest;
      farthest = k;
    } else if (k != farthest && from0(k) > from0(next)) {
      next = k;
    }
  }
  const std::pair<int, int> couplings[] = {{0, farthest}, {0, next}};
  Tpetra::MultiVector<double> x(map, 1), z(map, 1);
  {
    auto data = x.getDataNonConst(0);
    for (int k = 0; k < n; ++k) {
      data[k] = std::sin(0.37 * k + 0.1);
    }
  }
  for (const auto& [a, b] : couplings) {
    adhesion::LoadStiffness external;
    addSpring(external, a, b, 2.0);
    P.setCell(0, 0, H, mobility, &external);
    P.setShift(shift);
    P.apply(x, z);
    // The dense system.
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
    H.forEachEntry([&](int r, int c, double v) { A(r, c) += shift * v; });
    external.forEachEntry([&](int r, int c, double v) { A(r, c) += shift * v; });
    Eigen::VectorXd rhs(n);
    const auto xd = x.getData(0);
    for (int k = 0; k < n; ++k) {
      A(k, k) += 1.0 / 0.7;
      rhs[k] = xd[k] / 0.7;
    }
    const Eigen::VectorXd exact = A.partialPivLu().solve(rhs);
    const auto zd = z.getData(0);
    double worst = 0.0;
    for (int k = 0; k < n; ++k) {
      worst = std::max(worst, std::abs(zd[k] - exact[k]));
    }
    EXPECT_LT(worst, 1e-10 * exact.cwiseAbs().maxCoeff()) << "coupling " << a << "-" << b;
  }
}
