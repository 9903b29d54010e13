// Near-singular element integrals by adaptive subdivision, at the default tolerance, for
// targets down to 1/1000 of the element size away.
//
// Flat element: the solid angle has a closed form (Van Oosterom & Strackee 1983),
//   tan(Omega / 2) = a . (b x c) / (|a||b||c| + (a.b)|c| + (a.c)|b| + (b.c)|a|),
// a, b, c the vertices seen from the target, and the trace of the double-layer kernel is
// T_iik n_k = -6 (xh . n) / r^3, so int T_iik n_k dS = -6 x (the solid angle integrand).
// Curved element (from a sphere): the velocity induced by the element, f . int G dS, and
// its double layer, against a reference from the 19-point rule subdivided to 1e-13.
#include "OperatorTesting.hpp"

#include <capsula/greens/Wall3D.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/operators/AdaptiveQuadrature.hpp>
#include <capsula/operators/ContractedKernels.hpp>
#include <capsula/operators/ElementIntegrals.hpp>
#include <capsula/operators/OperatorParameters.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

using namespace capsula;
using namespace capsula::operators;
using mesh::Vec3;

// The policy instance an integrand evaluates its kernel through (the built-in ones are empty).
template <class Kernel>
const Kernel policy{};

const double defaultTolerance = DiscretisationParameters{}.nearSingularTolerance;
const auto& defaultRule()
{
  return quadrature::triangleRule(DiscretisationParameters{}.quadraturePoints);
}

template <std::size_t N>
double maxAbs(const std::array<double, N>& v)
{
  double m = 0.0;
  for (const double x : v) {
    m = std::max(m, std::abs(x));
  }
  return m;
}

template <std::size_t N>
double maxDifference(const std::array<double, N>& a, const std::array<double, N>& b)
{
  double m = 0.0;
  for (std::size_t k = 0; k < N; ++k) {
    m = std::max(m, std::abs(a[k] - b[k]));
  }
  return m;
}

double flatSolidAngle(const Vec3& x0, const Vec3& p0, const Vec3& p1, const Vec3& p2)
{
  const Vec3 a = p0 - x0, b = p1 - x0, c = p2 - x0;
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double numerator = a.dot(b.cross(c));
  const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
  return 2.0 * std::atan2(numerator, denominator);
}

// Targets near the element: above the centroid, above an edge midpoint, above a vertex,
// and in the element's plane beyond an edge, at distance d.
// (On a curved element "above" is along the surface normal at the parametric point.)
std::vector<Vec3> targets(const mesh::ElementNodes& x, double d)
{
  const mesh::ShapeParameters shape = mesh::shapeParameters(x);
  const auto above = [&](double xi, double eta, double offset) {
    const mesh::SurfacePoint s = mesh::evaluateSurfacePoint(x, shape, xi, eta);
    return Vec3(s.position + offset * s.normal);
  };
  const mesh::SurfacePoint mid = mesh::evaluateAtNode(x, shape, 3);
  const Vec3 inward = mid.normal.cross(mid.tangentXi).normalized(); // tangent plane, into the element
  return {above(1.0 / 3.0, 1.0 / 3.0, d), above(shape.alpha, 0.0, d), above(0.0, 0.0, d),
          Vec3(mid.position - d * inward), above(shape.alpha, 0.0, -d)};
}

TEST(NearSingular, FlatElementSolidAngleAndDoubleLayerTrace)
{
  const Vec3 p0(0.0, 0.0, 0.0), p1(0.2, 0.02, 0.0), p2(0.05, 0.17, 0.0);
  const mesh::ElementNodes x = {p0, p1, p2, 0.5 * (p0 + p1), 0.5 * (p1 + p2), 0.5 * (p2 + p0)};
  const ElementMap element(x, mesh::ShapeParameters{});
  const double size = (p1 - p0).norm();
  for (const double ratio : {1.0, 0.1, 0.01, 0.001}) {
    for (const Vec3& x0 : targets(x, ratio * size)) {
      const double exact = flatSolidAngle(x0, p0, p1, p2);
      const double solid =
          integrateAdaptively(element, SolidAngleIntegrand{x0.data()}, defaultRule(), defaultTolerance)[0];
      const auto dl =
          integrateAdaptively(element, DoubleLayerIntegrand<FreeSpace3DKernel>{&policy<FreeSpace3DKernel>, x0.data()},
                              defaultRule(), defaultTolerance);
      double trace = 0.0;
      for (int a = 0; a < 6; ++a) {
        trace += dl[9 * a] + dl[9 * a + 4] + dl[9 * a + 8];
      }
      // The scale of the solid angle seen this close is 2 pi; targets in the plane see 0
      // and the absolute error is judged against the size the angle would have above it.
      const double scale = std::max(std::abs(exact), 1e-2);
      EXPECT_NEAR(solid, exact, 1e-6 * scale) << "d/h = " << ratio;
      EXPECT_NEAR(trace, -6.0 * exact, 6e-6 * scale) << "d/h = " << ratio;
    }
  }
}

template <class Kernel>
void expectCurvedElementMatchesReference(const Vec3& cellCentre)
{
  mesh::Placement placement;
  placement.centre = cellCentre;
  const auto sphere = mesh::makeSphere(2, 1.0, placement);
  const auto& fine = quadrature::triangleRule(19);
  // A load that varies over the element (values at its six nodes, LoadDensity layout).
  const double load[18] = {0.3, -1.1, 0.6, 0.5, -0.9, 0.4, 0.1, -1.3, 0.8,
                           0.4, -1.0, 0.5, 0.3, -1.2, 0.7, 0.2, -1.1, 0.6};
  for (const int e : {5, 211}) {
    const mesh::ElementNodes x = sphere.elementNodes(e);
    const ElementMap element(x, mesh::shapeParameters(x));
    const double size = std::max({(x[1] - x[0]).norm(), (x[2] - x[1]).norm(), (x[0] - x[2]).norm()});
    for (const double ratio : {1.0, 0.1, 0.01}) {
      for (const Vec3& x0 : targets(x, ratio * size)) {
        const LoadedSingleLayerIntegrand<Kernel> single{&policy<Kernel>, x0.data(), load};
        const DoubleLayerIntegrand<Kernel> dbl{&policy<Kernel>, x0.data()};
        const auto u = integrateAdaptively(element, single, defaultRule(), defaultTolerance);
        const auto uRef = integrateAdaptively(element, single, fine, 1e-13);
        const auto d = integrateAdaptively(element, dbl, defaultRule(), defaultTolerance);
        const auto dRef = integrateAdaptively(element, dbl, fine, 1e-13);
        // The accuracy asked of the subdivision: 1e-6 relative to the element's contribution.
        EXPECT_LT(maxDifference(u, uRef), 1e-6 * maxAbs(uRef)) << "element " << e << " d/h = " << ratio;
        EXPECT_LT(maxDifference(d, dRef), 1e-6 * maxAbs(dRef)) << "element " << e << " d/h = " << ratio;
      }
    }
  }
}

TEST(NearSingular, CurvedElementFreeSpace)
{
  expectCurvedElementMatchesReference<FreeSpace3DKernel>(Vec3::Zero());
}

TEST(NearSingular, CurvedElementWall)
{
  expectCurvedElementMatchesReference<Wall3DKernel>(Vec3(0.0, 1.3, 0.0));
}

TEST(NearSingular, RoundOffAroundZeroStopsAtTheBudget)
{
  // The greens wall stresslet with its pole on the wall is zero up to round-off: the
  // magnitude gives no scale and every comparison fails. The budget ends the work.
  const auto sphere = mesh::makeSphere(2, 1.0, {Vec3(0.0, 1.05, 0.0), mesh::Mat3::Identity()});
  const mesh::ElementNodes x = sphere.elementNodes(0);
  const ElementMap element(x, mesh::shapeParameters(x));
  const mesh::Vec3 foot = mesh::surfacePosition(x, mesh::shapeParameters(x), 1.0 / 3.0, 1.0 / 3.0);
  const Vec3 x0(foot[0], 0.0, foot[2]);
  const DoubleLayerIntegrand<greens::Wall3D> integrand{&policy<greens::Wall3D>, x0.data()};
  const double poles[1][3] = {{x0[0], x0[1], x0[2]}};
  AdaptiveElementQuadrature<DoubleLayerIntegrand<greens::Wall3D>> adaptive(element, integrand, defaultRule(),
                                                                           defaultTolerance, poles, 1);
  const auto value = adaptive.integrate();
  EXPECT_GT(adaptive.ruleApplications(), maxRuleApplications - 4); // it did run into the budget
  EXPECT_LE(adaptive.ruleApplications(), maxRuleApplications);
  EXPECT_LT(maxAbs(value), 1e-12);
}

TEST(NearSingular, RefinementIsLocal)
{
  // Targets 1e-2, 1e-3 and 1e-4 element sizes above the centroid: the subdivision refines
  // towards the foot of the target only, so each tenfold approach adds about the same
  // work (log(1/d)), not a hundredfold more (1/d^2).
  const auto sphere = mesh::makeSphere(2, 1.0);
  const mesh::ElementNodes x = sphere.elementNodes(0);
  const ElementMap element(x, mesh::shapeParameters(x));
  const mesh::SurfacePoint foot = mesh::evaluateSurfacePoint(x, mesh::shapeParameters(x), 1.0 / 3.0, 1.0 / 3.0);
  std::vector<int> work;
  for (const double ratio : {1e-2, 1e-3, 1e-4}) {
    const Vec3 x0 = foot.position + ratio * (x[1] - x[0]).norm() * foot.normal;
    const SingleLayerIntegrand<FreeSpace3DKernel> integrand{&policy<FreeSpace3DKernel>, x0.data()};
    const double poles[1][3] = {{x0[0], x0[1], x0[2]}};
    AdaptiveElementQuadrature<SingleLayerIntegrand<FreeSpace3DKernel>> adaptive(element, integrand, defaultRule(),
                                                                                defaultTolerance, poles, 1);
    adaptive.integrate();
    work.push_back(adaptive.ruleApplications());
    std::printf("target %.0e h above an element: %d rule applications\n", ratio, work.back());
  }
  EXPECT_LT(work[2] - work[1], 2 * (work[1] - work[0]) + 50);
  EXPECT_LT(work[1], 3000);
}

} // namespace
