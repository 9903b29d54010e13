// Tangential node redistribution (NodeRedistribution.hpp): what it must carry over exactly,
// what it must improve, and what it must leave alone.
#include <capsula/core/Error.hpp>
#include <capsula/mesh/Icosphere.hpp>
#include <capsula/mesh/Measures.hpp>
#include <capsula/mesh/MeshQuality.hpp>
#include <capsula/mesh/NodeRedistribution.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace capsula::mesh;

namespace {

// The unit icosphere with every node turned about the z axis by `twist` z radians: the
// nodes stay on the sphere and the elements are sheared, most near the equator (level 2,
// twist 1: smallest angle 22.7 degrees instead of 54.4).
std::vector<double> twistedSphere(const SurfaceMesh& sphere, double twist)
{
  std::vector<double> x = sphere.positions();
  for (std::size_t i = 0; i < x.size(); i += 3) {
    const double angle = twist * x[i + 2];
    const double c = std::cos(angle), s = std::sin(angle);
    const double px = x[i], py = x[i + 1];
    x[i] = c * px - s * py;
    x[i + 1] = s * px + c * py;
  }
  return x;
}

double volume(SurfaceMesh mesh, const std::vector<double>& x)
{
  mesh.setPositions(x);
  return enclosedVolume(mesh);
}

RedistributionOptions withoutVolumeFix(int passes = 3)
{
  RedistributionOptions options;
  options.passes = passes;
  options.preserveVolume = false;
  return options;
}

} // namespace

// The reference positions are interpolated with the same element maps as the positions,
// so a field that is an affine function of x is carried over exactly: X' = A x' + b to
// round-off. A wrong element, a wrong (xi, eta) or a map parametrised differently for x
// and X breaks this by O(h^2) (1e-3 and more).
TEST(NodeRedistribution, CarriesAnAffineFieldExactly)
{
  const SurfaceMesh sphere = makeIcosphere(2);
  const auto x = twistedSphere(sphere, 1.0);
  Mat3 A;
  A << 1.1, 0.2, -0.3, 0.05, 0.9, 0.1, -0.2, 0.15, 1.3;
  const Vec3 b(0.3, -0.1, 0.2);
  std::vector<double> X(x.size());
  for (std::size_t i = 0; i < x.size(); i += 3) {
    const Vec3 Xi = A * Vec3(x[i], x[i + 1], x[i + 2]) + b;
    std::copy(Xi.data(), Xi.data() + 3, X.begin() + static_cast<std::ptrdiff_t>(i));
  }
  const auto moved = redistributeNodes(sphere, x, X, withoutVolumeFix());
  ASSERT_EQ(moved.passes, 3);
  EXPECT_GT(moved.maxDisplacement, 0.05); // the nodes really moved (0.09 measured)
  double worst = 0.0;
  for (std::size_t i = 0; i < x.size(); i += 3) {
    const Vec3 expected = A * Vec3(moved.positions[i], moved.positions[i + 1], moved.positions[i + 2]) + b;
    for (int d = 0; d < 3; ++d) {
      worst = std::max(worst, std::abs(moved.reference[i + static_cast<std::size_t>(d)] - expected[d]));
    }
  }
  EXPECT_LT(worst, 1e-13); // round-off of a 6-term sum of O(1) numbers
}

// A sheared mesh gets better elements. Measured (twist 1): level 1 24.1 -> 53.7 degrees,
// level 2 22.7 -> 38.9 in 20 passes (Laplacian smoothing undoes a long-wave shear slowly on
// a fine mesh, which is why a run redistributes as soon as the angle falls below its
// trigger, before the shear has grown).
TEST(NodeRedistribution, ImprovesAShearedMesh)
{
  RedistributionOptions options;
  options.passes = 20;
  for (const auto& [level, atLeast] : {std::pair{1, 50.0}, std::pair{2, 35.0}}) {
    const SurfaceMesh sphere = makeIcosphere(level);
    const auto x = twistedSphere(sphere, 1.0);
    const auto moved = redistributeNodes(sphere, x, x, options);
    EXPECT_LT(moved.minAngleBefore, 25.0) << "level " << level;
    EXPECT_GT(moved.minAngleAfter, atLeast) << "level " << level;
    SurfaceMesh result = sphere;
    result.setPositions(moved.positions);
    EXPECT_NEAR(meshQuality(result).minAngle, moved.minAngleAfter, 1e-12); // the report is the result's
  }
}

// The icosphere is already as good as smoothing makes it: nothing moves.
TEST(NodeRedistribution, LeavesAGoodMeshAlone)
{
  const SurfaceMesh sphere = makeIcosphere(2);
  const auto moved = redistributeNodes(sphere, sphere.positions(), sphere.positions());
  EXPECT_EQ(moved.passes, 0);
  EXPECT_EQ(moved.positions, sphere.positions());
  EXPECT_EQ(moved.maxDisplacement, 0.0);
}

// Re-interpolating the quadratic elements shrinks a curved surface, by about h^4 (twist 1,
// 3 passes: -2.6e-3, -1.7e-4, -7.4e-6 at levels 1-3); the default normal
// offset restores it to round-off (the Newton loop stops at 1e-13).
TEST(NodeRedistribution, KeepsTheEnclosedVolume)
{
  std::vector<double> shrinkage;
  for (int level = 1; level <= 3; ++level) {
    const SurfaceMesh sphere = makeIcosphere(level);
    const auto x = twistedSphere(sphere, 1.0);
    const double before = volume(sphere, x);
    const auto plain = redistributeNodes(sphere, x, x, withoutVolumeFix());
    shrinkage.push_back(1.0 - volume(sphere, plain.positions) / before);
    EXPECT_GT(shrinkage.back(), 0.0) << "level " << level; // always inwards
    const auto kept = redistributeNodes(sphere, x, x, RedistributionOptions{});
    EXPECT_LT(std::abs(volume(sphere, kept.positions) / before - 1.0), 1e-12) << "level " << level;
    EXPECT_GT(kept.volumeOffset, 0.0) << "level " << level; // outwards, against the shrinkage
  }
  // Order of the shrinkage in h (h halves per level): measured 4.0 and 4.5; > 3.5 holds
  // it to the interpolation error of quadratic elements (a projection onto flat facets,
  // or onto each pass's own result, would shrink at order 2-3).
  EXPECT_GT(std::log2(shrinkage[0] / shrinkage[1]), 3.5);
  EXPECT_GT(std::log2(shrinkage[1] / shrinkage[2]), 3.5);
}

// The result is computed from the surface before each pass: renumbering nothing, but
// running it twice from the same input gives the same bits (the scene relies on every rank
// doing the same arithmetic).
TEST(NodeRedistribution, IsDeterministic)
{
  const SurfaceMesh sphere = makeIcosphere(2);
  const auto x = twistedSphere(sphere, 1.5);
  const auto a = redistributeNodes(sphere, x, x);
  const auto b = redistributeNodes(sphere, x, x);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.reference, b.reference);
}

TEST(NodeRedistribution, RejectsBadInput)
{
  const SurfaceMesh sphere = makeIcosphere(1);
  const auto& x = sphere.positions();
  std::vector<double> shortArray(x.begin(), x.end() - 3);
  EXPECT_THROW(redistributeNodes(sphere, shortArray, x), capsula::core::InputError);
  EXPECT_THROW(redistributeNodes(sphere, x, shortArray), capsula::core::InputError);
  RedistributionOptions options;
  options.relaxation = 0.0;
  EXPECT_THROW(redistributeNodes(sphere, x, x, options), capsula::core::InputError);
  options.relaxation = 0.5;
  options.passes = 0;
  EXPECT_THROW(redistributeNodes(sphere, x, x, options), capsula::core::InputError);
}

// The closest point of an element is found from the element's own map: a point of the
// element, lifted off it along its normal, projects back onto it.
TEST(NodeRedistribution, ClosestPointOnElement)
{
  const SurfaceMesh sphere = makeIcosphere(2);
  const auto nodes = sphere.elementNodes(7);
  const auto p = shapeParameters(nodes);
  const SurfacePoint s = evaluateSurfacePoint(nodes, p, 0.2, 0.3);
  const auto found = closestPointOnElement(nodes, p, s.position + 0.01 * s.normal);
  EXPECT_NEAR(found.xi, 0.2, 1e-3); // the normal of a curved element is not quite the closest direction
  EXPECT_NEAR(found.eta, 0.3, 1e-3);
  EXPECT_NEAR(std::sqrt(found.squaredDistance), 0.01, 1e-5);
}
