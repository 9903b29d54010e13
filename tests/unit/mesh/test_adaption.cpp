// Red-green-blue refinement with quadratic node placement, and curvature-driven adaption
// (thesis Section 4.7, eq 4.3): the refined mesh is closed and conforming, its new nodes
// lie on the parents' quadratic maps in every configuration carried along, the discrete
// surface (area, volume) is kept, and element quality stays bounded.
#include <capsula/core/Error.hpp>
#include <capsula/mesh/Adaption.hpp>
#include <capsula/mesh/Icosphere.hpp>
#include <capsula/mesh/Measures.hpp>
#include <capsula/mesh/MeshQuality.hpp>
#include <capsula/mesh/Refinement.hpp>
#include <capsula/mesh/Shapes.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <utility>
#include <vector>

using namespace capsula::mesh;

namespace {

/// Independent of the SurfaceMesh constructor's own checks: every directed vertex edge
/// (a -> b) of the connectivity occurs once and its reverse once (closed, two elements
/// per edge, consistent orientation), both with the same midside node, and
/// V - E + F = 2 (a sphere).
void expectClosedAndConforming(const SurfaceMesh& mesh)
{
  std::map<std::pair<int, int>, std::pair<int, int>> directed; // (a, b) -> (count, mid)
  for (const ElementConnectivity& el : mesh.elements()) {
    for (int k = 0; k < 3; ++k) {
      const auto l = localEdgeNodes(k);
      auto& entry = directed[{el[static_cast<std::size_t>(l[0])], el[static_cast<std::size_t>(l[1])]}];
      ++entry.first;
      entry.second = el[static_cast<std::size_t>(l[2])];
    }
  }
  int vertexEdges = 0;
  for (const auto& [ab, entry] : directed) {
    ASSERT_EQ(entry.first, 1) << "edge " << ab.first << "-" << ab.second << " traversed twice the same way";
    const auto reverse = directed.find({ab.second, ab.first});
    ASSERT_NE(reverse, directed.end()) << "edge " << ab.first << "-" << ab.second << " has one element";
    ASSERT_EQ(reverse->second.second, entry.second) << "two midside nodes on one edge";
    ++vertexEdges;
  }
  EXPECT_EQ(mesh.numVertexNodes() - vertexEdges / 2 + mesh.numElements(), 2);
}

/// (xi, eta) with x(xi, eta) closest to `target` on the element map (Gauss-Newton from
/// the centroid), and the remaining distance.
std::pair<std::array<double, 2>, double> parametricPoint(const ElementNodes& x, const ShapeParameters& p,
                                                         const Vec3& target)
{
  std::array<double, 2> c{1.0 / 3.0, 1.0 / 3.0};
  for (int it = 0; it < 30; ++it) {
    const SurfacePoint s = evaluateSurfacePoint(x, p, c[0], c[1]);
    Eigen::Matrix<double, 3, 2> J;
    J << s.tangentXi, s.tangentEta;
    const Eigen::Vector2d step = J.colPivHouseholderQr().solve(target - s.position);
    c[0] += step[0];
    c[1] += step[1];
  }
  return {c, (surfacePosition(x, p, c[0], c[1]) - target).norm()};
}

std::vector<int> elementsWithCentroidAbove(const SurfaceMesh& mesh, const Vec3& direction, double height)
{
  std::vector<int> marked;
  for (int e = 0; e < mesh.numElements(); ++e) {
    const ElementNodes x = mesh.elementNodes(e);
    if ((x[0] + x[1] + x[2]).dot(direction) / 3.0 > height) {
      marked.push_back(e);
    }
  }
  return marked;
}

struct SplitCounts {
  int kept = 0, green = 0, blue = 0, red = 0;
};

SplitCounts countSplits(const std::vector<ElementSplit>& splits)
{
  SplitCounts c;
  for (ElementSplit s : splits) {
    c.kept += s == ElementSplit::Kept;
    c.green += s == ElementSplit::Green;
    c.blue += s == ElementSplit::Blue;
    c.red += s == ElementSplit::Red;
  }
  return c;
}

double relativeChange(double after, double before)
{
  return (after - before) / before;
}

/// Every node of every child lies on its parent's map, the new ones at the parametric
/// midpoints of the child's edges; every field was interpolated with that same map; and
/// the child's map with the parent's parametrisation is the parent's map.
void expectNodesOnParentMaps(const SurfaceMesh& old, const std::vector<std::vector<double>>& oldFields,
                             const RefinedMesh& refined)
{
  for (int e = 0; e < refined.mesh.numElements(); ++e) {
    const int parent = refined.parentElement[static_cast<std::size_t>(e)];
    const ElementNodes x = old.elementNodes(parent);
    const ShapeParameters p = shapeParameters(x);
    std::array<std::array<double, 2>, 6> c{};
    for (int j = 0; j < 6; ++j) {
      const int node = refined.mesh.element(e)[static_cast<std::size_t>(j)];
      const auto [point, distance] = parametricPoint(x, p, refined.mesh.position(node));
      c[static_cast<std::size_t>(j)] = point;
      // On the parent's current map to round-off (coordinates ~1).
      ASSERT_LT(distance, 1e-13) << "element " << e << " node " << node;
      EXPECT_GT(std::min({point[0], point[1], 1.0 - point[0] - point[1]}), -1e-12);
      double phi[6];
      shapeFunctions(p, point[0], point[1], phi);
      for (std::size_t f = 0; f < oldFields.size(); ++f) {
        const std::size_t m = oldFields[f].size() / static_cast<std::size_t>(old.numNodes());
        for (std::size_t d = 0; d < m; ++d) {
          double expected = 0.0;
          for (std::size_t i = 0; i < 6; ++i) {
            expected += phi[i] * oldFields[f][m * static_cast<std::size_t>(old.element(parent)[i]) + d];
          }
          // Same map at the same point: round-off of a 6-term sum.
          EXPECT_NEAR(refined.fields[f][m * static_cast<std::size_t>(node) + d], expected, 1e-12)
              << "field " << f << " node " << node;
        }
      }
    }
    for (int k = 0; k < 3; ++k) {
      const auto l = localEdgeNodes(k);
      if (refined.mesh.element(e)[static_cast<std::size_t>(l[2])] < old.numNodes()) {
        continue; // an old midside node: it stays at the parent's eq 3.17 point
      }
      for (int d = 0; d < 2; ++d) {
        const double mid = 0.5 * (c[static_cast<std::size_t>(l[0])][static_cast<std::size_t>(d)] +
                                  c[static_cast<std::size_t>(l[1])][static_cast<std::size_t>(d)]);
        // Newton's answer is exact to ~1e-15; 1e-11 leaves room for its conditioning.
        EXPECT_NEAR(c[static_cast<std::size_t>(l[2])][static_cast<std::size_t>(d)], mid, 1e-11)
            << "child " << e << " edge " << k;
      }
    }
    // With the parametrisation it inherits from its parent (the affine preimages of its
    // nodes' parent coordinates), the child's map IS the parent's map: the quadratic
    // placement is exact. (eq 3.17 gives the child a slightly different one.)
    const Eigen::Vector2d c0(c[0][0], c[0][1]), c1(c[1][0], c[1][1]), c2(c[2][0], c[2][1]);
    const auto fraction = [](const Eigen::Vector2d& from, const Eigen::Vector2d& to, const std::array<double, 2>& at) {
      const Eigen::Vector2d d = to - from;
      return (Eigen::Vector2d(at[0], at[1]) - from).dot(d) / d.squaredNorm();
    };
    const ShapeParameters inherited{fraction(c0, c1, c[3]), fraction(c0, c2, c[5]), fraction(c2, c1, c[4])};
    const ElementNodes child = refined.mesh.elementNodes(e);
    for (const auto& [xi, eta] : std::vector<std::pair<double, double>>{{0.2, 0.2}, {0.6, 0.3}, {0.1, 0.8}}) {
      const Eigen::Vector2d q = c0 + xi * (c1 - c0) + eta * (c2 - c0);
      EXPECT_LT((surfacePosition(child, inherited, xi, eta) - surfacePosition(x, p, q[0], q[1])).norm(), 1e-13)
          << "child " << e;
    }
  }
}

} // namespace

TEST(Refinement, PolarCapOfASphereStaysClosedConformingAndKeepsItsVolume)
{
  const SurfaceMesh sphere = makeSphere(2, 1.3);
  const std::vector<int> marked = elementsWithCentroidAbove(sphere, Vec3::UnitZ(), 0.7 * 1.3);
  const RefinedMesh refined = refineElements(sphere, marked);
  expectClosedAndConforming(refined.mesh);

  const SplitCounts c = countSplits(refined.splits);
  EXPECT_EQ(refined.splits, refinementPlan(sphere, marked));
  EXPECT_EQ(refined.mesh.numElements(), c.kept + 2 * c.green + 3 * c.blue + 4 * c.red);
  EXPECT_EQ(static_cast<int>(refined.parentElement.size()), refined.mesh.numElements());
  for (int e : marked) {
    EXPECT_EQ(refined.splits[static_cast<std::size_t>(e)], ElementSplit::Red);
  }
  // The closure is local: a band of green/blue elements around the cap, not the sphere.
  EXPECT_LT(c.red + c.green + c.blue, 2 * static_cast<int>(marked.size()));
  // Old nodes keep their numbers and positions.
  for (int i = 0; i < sphere.numNodes(); ++i) {
    EXPECT_EQ(refined.mesh.position(i), sphere.position(i));
  }

  // New nodes lie on the quadratic parent surface: the volume (exact for the discrete
  // surface at N_Q = 6) changes only by the re-parametrisation of the children (each child
  // map interpolates the parent at six points, with its own eq 3.17 spacing). Measured
  // 1.5e-7 at level 2 (5e-9 at level 3).
  const double dV = relativeChange(enclosedVolume(refined.mesh), enclosedVolume(sphere));
  const double dA = relativeChange(surfaceArea(refined.mesh), surfaceArea(sphere));
  const MeshQuality before = meshQuality(sphere), after = meshQuality(refined.mesh);
  std::printf("sphere level 2, %zu marked: N_E %d -> %d (red %d, blue %d, green %d), dV/V = %.2e, "
              "dA/A = %.2e, min angle %.1f -> %.1f deg\n",
              marked.size(), sphere.numElements(), refined.mesh.numElements(), c.red, c.blue, c.green, dV, dA,
              before.minAngle, after.minAngle);
  EXPECT_LT(std::abs(dV), 1e-6);
  EXPECT_LT(std::abs(dA), 1e-6);
  // Bisecting a near-equilateral element halves one angle: ~30 degrees.
  EXPECT_GT(after.minAngle, 0.5 * before.minAngle);
}

TEST(Refinement, NewNodesLieOnTheParentMapsInBothConfigurations)
{
  // The reference configuration differs from the current one; both share the node
  // numbering of the icosphere. A scalar field rides along too.
  const Vec3 ellipsoidAxes(1.2, 0.7, 1.6);
  for (const bool sphereIsCurrent : {true, false}) {
    const SurfaceMesh sphere = makeSphere(2, 1.0);
    const SurfaceMesh ellipsoid = makeEllipsoid(2, ellipsoidAxes);
    const SurfaceMesh& current = sphereIsCurrent ? sphere : ellipsoid; // ellipsoid: alpha != 1/2
    const SurfaceMesh& reference = sphereIsCurrent ? ellipsoid : sphere;
    std::vector<double> scalar;
    for (int i = 0; i < reference.numNodes(); ++i) {
      const Vec3 X = reference.position(i);
      scalar.push_back(std::sin(2.0 * X[0]) + X[1] * X[2]);
    }
    const std::vector<std::vector<double>> fields{reference.positions(), scalar};
    const RefinedMesh refined =
        refineElements(current, elementsWithCentroidAbove(current, Vec3(1.0, 1.0, 1.0).normalized(), 0.6), fields);
    expectClosedAndConforming(refined.mesh);
    ASSERT_EQ(refined.fields.size(), 2u);
    ASSERT_EQ(refined.fields[0].size(), refined.mesh.positions().size());
    ASSERT_EQ(static_cast<int>(refined.fields[1].size()), refined.mesh.numNodes());
    expectNodesOnParentMaps(current, fields, refined);
    // The reference mesh is a valid closed surface too, with the same connectivity.
    const SurfaceMesh refinedReference(refined.fields[0], refined.mesh.elements());
    const double dV = relativeChange(enclosedVolume(refinedReference), enclosedVolume(reference));
    std::printf("%s current: reference volume change %.2e\n", sphereIsCurrent ? "sphere" : "ellipsoid", dV);
    // The reference nodes are placed with the CURRENT parametrisation (material
    // consistency), so the reference surface's own eq 3.17 parametrisation differs from the
    // one that placed them: its volume moves by 6e-6 (sphere current) and 1.2e-5
    // (ellipsoid current) at this coarse level, a tenth of its discretisation error (1.4e-4).
    EXPECT_LT(std::abs(dV), 3e-5);
  }
}

TEST(Refinement, CarryingThePositionsAlongReproducesThemExactly)
{
  // A field equal to the positions is interpolated by the same arithmetic.
  const SurfaceMesh mesh = makeBiconcaveCell(2);
  const RefinedMesh refined = refineElements(mesh, {0, 7, 19, 100}, {mesh.positions()});
  EXPECT_EQ(refined.fields[0], refined.mesh.positions());
}

TEST(Refinement, UniformRefinementOfTheIcosphere)
{
  const SurfaceMesh coarse = makeIcosphere(2);
  std::vector<int> all(static_cast<std::size_t>(coarse.numElements()));
  for (int e = 0; e < coarse.numElements(); ++e) {
    all[static_cast<std::size_t>(e)] = e;
  }
  const RefinedMesh refined = refineElements(coarse, all);
  EXPECT_EQ(refined.mesh.numElements(), 1280); // Table 3.1, level 3
  EXPECT_EQ(refined.mesh.numNodes(), 2562);
  EXPECT_EQ(countSplits(refined.splits).red, 320);
  expectClosedAndConforming(refined.mesh);
  // Only the children's own eq 3.17 parametrisation moves the surface: the volume changes
  // by 2.5e-8, against a discretisation error of 1.4e-4 of the level-2 sphere.
  EXPECT_LT(std::abs(relativeChange(enclosedVolume(refined.mesh), enclosedVolume(coarse))), 1e-7);
  // Red children are nearly similar to their parents (the midside nodes that become their
  // vertices sit just off the chords): the smallest angle is kept to within 2 degrees.
  EXPECT_NEAR(meshQuality(refined.mesh).minAngle, meshQuality(coarse).minAngle, 2.0);
}

TEST(Refinement, OneMarkedElementRefinesOnlyItsNeighbourhood)
{
  // Longest-edge closure spreads along longest edges only: marking any one element of
  // the level-3 prolate ellipsoid bisects its three neighbours and a few more (measured:
  // 4 to 11, 5.3 on average), never a growing region.
  const SurfaceMesh mesh = makeEllipsoid(3, Vec3(1.0, 0.5, 2.0));
  int most = 0;
  double total = 0.0;
  for (int e = 0; e < mesh.numElements(); ++e) {
    const SplitCounts c = countSplits(refinementPlan(mesh, {e}));
    ASSERT_EQ(c.red, 1);
    ASSERT_GE(c.green + c.blue, 3) << "element " << e;
    most = std::max(most, c.green + c.blue);
    total += c.green + c.blue;
  }
  EXPECT_LE(most, 16);
  EXPECT_LT(total / mesh.numElements(), 8.0);
}

TEST(Refinement, RepeatedRandomRefinementKeepsHalfTheSmallestAngle)
{
  // Longest-edge bisection (green, blue) keeps every angle above half the smallest
  // angle it started from, red children are similar: over many passes the smallest
  // angle of the mesh stays above half the initial one (Rivara 1984).
  SurfaceMesh mesh = makeEllipsoid(1, Vec3(1.0, 0.5, 2.0));
  const double initial = meshQuality(mesh).minAngle;
  std::mt19937 random(7);
  for (int pass = 0; pass < 6; ++pass) {
    std::vector<int> marked;
    std::uniform_int_distribution<int> pick(0, mesh.numElements() - 1);
    for (int i = 0; i < 1 + mesh.numElements() / 20; ++i) {
      marked.push_back(pick(random));
    }
    RefinedMesh refined = refineElements(mesh, marked);
    expectClosedAndConforming(refined.mesh);
    mesh = std::move(refined.mesh);
    EXPECT_GE(meshQuality(mesh).minAngle, 0.5 * initial) << "pass " << pass;
  }
  std::printf("6 random passes: N_E 80 -> %d, min angle %.1f -> %.1f deg\n", mesh.numElements(), initial,
              meshQuality(mesh).minAngle);
}

TEST(Refinement, NothingMarkedGivesTheSameMesh)
{
  const SurfaceMesh mesh = makeIcosphere(1);
  const RefinedMesh refined =
      refineElements(mesh, {}, {std::vector<double>(static_cast<std::size_t>(mesh.numNodes()), 1.0)});
  EXPECT_EQ(refined.mesh.elements(), mesh.elements());
  EXPECT_EQ(refined.mesh.positions(), mesh.positions());
  EXPECT_EQ(countSplits(refined.splits).kept, mesh.numElements());
}

TEST(Refinement, RejectsBadInput)
{
  const SurfaceMesh mesh = makeIcosphere(1);
  EXPECT_THROW(refineElements(mesh, {80}), capsula::core::InputError);
  EXPECT_THROW(refineElements(mesh, {-1}), capsula::core::InputError);
  EXPECT_THROW(refineElements(mesh, {0}, {std::vector<double>(5, 0.0)}), capsula::core::InputError);
  EXPECT_THROW(refineElements(mesh, {0}, {std::vector<double>()}), capsula::core::InputError);
}

TEST(Adaption, QualityFunctionOfEq4_3)
{
  // On a sphere of radius R, kappa_max = 1/R at every node, so Q_e = A_e / R^2.
  const double R = 2.5;
  const SurfaceMesh sphere = makeSphere(2, R);
  NodeCurvatures exact{std::vector<double>(static_cast<std::size_t>(sphere.numNodes()), 1.0 / R),
                       std::vector<double>(static_cast<std::size_t>(sphere.numNodes()), 1.0 / (R * R)),
                       std::vector<Vec3>(static_cast<std::size_t>(sphere.numNodes()), Vec3::UnitZ())};
  const std::vector<double> q = adaptionQuality(sphere, exact);
  const std::vector<double> areas = elementAreas(sphere);
  for (std::size_t e = 0; e < q.size(); ++e) {
    // |kappa_max| = |kappa| + sqrt(kappa^2 - K): at an umbilic the square root turns the
    // round-off of kappa^2 - K (~1e-16 kappa^2) into ~1e-8 kappa.
    EXPECT_NEAR(q[e], areas[e] / (R * R), 1e-7 * q[e]);
  }
  EXPECT_EQ(indicesAtOrAbove({0.1, 0.2, 0.3, 0.19999}, 0.2), (std::vector<int>{1, 2}));
}

TEST(Adaption, ProlateEllipsoidRefinesTowardsItsTips)
{
  // Repeated adaption (eq 4.3, threshold 0.2) of the prolate ellipsoid b/a = 0.5,
  // c/a = 2, carrying the reference positions along.
  SurfaceMesh mesh = makeEllipsoid(2, Vec3(1.0, 0.5, 2.0));
  std::vector<double> reference = mesh.positions();
  const double initialMinAngle = meshQuality(mesh).minAngle;
  int pass = 0;
  for (; pass < 8; ++pass) {
    const std::vector<double> q = adaptionQuality(mesh, quadraticFitCurvature(mesh));
    const double maxQ = *std::max_element(q.begin(), q.end());
    RefinedMesh refined = adaptToCurvature(mesh, {reference});
    const SplitCounts c = countSplits(refined.splits);
    for (int e : indicesAtOrAbove(q, 0.2)) {
      EXPECT_EQ(refined.splits[static_cast<std::size_t>(e)], ElementSplit::Red);
    }
    if (refined.mesh.numElements() == mesh.numElements()) {
      EXPECT_LT(maxQ, 0.2);
      break;
    }
    expectClosedAndConforming(refined.mesh);
    const double dV = relativeChange(enclosedVolume(refined.mesh), enclosedVolume(mesh));
    const double dA = relativeChange(surfaceArea(refined.mesh), surfaceArea(mesh));
    std::printf("adaption pass %d: max Q %.2f, N_E %d -> %d (red %d, blue %d, green %d), dV/V %.1e, dA/A %.1e, "
                "min angle %.1f deg\n",
                pass, maxQ, mesh.numElements(), refined.mesh.numElements(), c.red, c.blue, c.green, dV, dA,
                meshQuality(refined.mesh).minAngle);
    // The discrete surface is kept up to the children's re-parametrisation (< 3e-6
    // measured on this coarse, strongly curved mesh).
    EXPECT_LT(std::abs(dV), 1e-5);
    EXPECT_LT(std::abs(dA), 1e-5);
    EXPECT_GE(meshQuality(refined.mesh).minAngle, 0.5 * initialMinAngle);
    // The reference rode along on the same maps; here it equals the positions.
    EXPECT_EQ(refined.fields[0], refined.mesh.positions());
    reference = std::move(refined.fields[0]);
    mesh = std::move(refined.mesh);
  }
  EXPECT_LT(pass, 8) << "adaption did not settle";
  // Small elements at the tips (|kappa_max| = 8), larger ones on the flanks (2-4).
  const std::vector<double> areas = elementAreas(mesh);
  double largestAtTips = 0.0, largestOnFlanks = 0.0;
  for (int e = 0; e < mesh.numElements(); ++e) {
    const double z = std::abs(mesh.elementNodes(e)[0][2]);
    double& largest = z > 1.9 ? largestAtTips : largestOnFlanks;
    largest = std::max(largest, areas[static_cast<std::size_t>(e)]);
  }
  std::printf("largest element area: %.2e at the tips (|z| > 1.9), %.2e elsewhere\n", largestAtTips, largestOnFlanks);
  EXPECT_LT(4.0 * largestAtTips, largestOnFlanks);
}

TEST(Adaption, RefinedDeformedShapeKeepsItsAreaAndVolume)
{
  // A biconcave cell: curvature-marked refinement keeps the discrete surface up to the
  // children's own eq 3.17 parametrisation (their chord-length alpha, beta, gamma differ
  // slightly from the parametric midpoints the parent put them at). Measure how far the
  // children leave the parent surface (child points projected onto the parent map).
  const SurfaceMesh cell = makeBiconcaveCell(3);
  AdaptionOptions options;
  options.curvature = CurvatureMethod::ElementAverage;
  options.threshold = 0.08; // Q reaches 0.12 at the rim at level 3: refines ~1/5 of the cell
  const RefinedMesh refined = adaptToCurvature(cell, {}, options);
  const SplitCounts c = countSplits(refined.splits);
  ASSERT_GT(c.red, 0);
  ASSERT_GT(c.kept, 0);
  expectClosedAndConforming(refined.mesh);
  double deviation = 0.0;
  for (int e = 0; e < refined.mesh.numElements(); ++e) {
    const int parent = refined.parentElement[static_cast<std::size_t>(e)];
    if (refined.splits[static_cast<std::size_t>(parent)] == ElementSplit::Kept) {
      continue;
    }
    const ElementNodes child = refined.mesh.elementNodes(e);
    const ElementNodes x = cell.elementNodes(parent);
    for (const auto& [xi, eta] :
         std::vector<std::pair<double, double>>{{1.0 / 3, 1.0 / 3}, {0.25, 0.25}, {0.6, 0.2}, {0.1, 0.7}}) {
      deviation = std::max(
          deviation,
          parametricPoint(x, shapeParameters(x), surfacePosition(child, shapeParameters(child), xi, eta)).second);
    }
  }
  const double dV = relativeChange(enclosedVolume(refined.mesh), enclosedVolume(cell));
  const double dA = relativeChange(surfaceArea(refined.mesh, 13), surfaceArea(cell, 13));
  // For scale: the area's own quadrature error, N_Q = 7 against 13.
  const double quadrature = relativeChange(surfaceArea(cell, 7), surfaceArea(cell, 13));
  std::printf("biconcave level 3: N_E %d -> %d (red %d, blue %d, green %d), dV/V %.1e, dA/A %.1e "
              "(N_Q = 7 vs 13 on the parent: %.1e), child-to-parent surface distance %.1e (cell radius 1)\n",
              cell.numElements(), refined.mesh.numElements(), c.red, c.blue, c.green, dV, dA, quadrature, deviation);
  // Measured 1.2e-5, far inside the O(h^3) distance of the mesh from the true cell.
  EXPECT_LT(deviation, 5e-5);
  // Measured 3e-7 and 1.4e-7: the re-parametrisation, not quadrature (6e-9 at N_Q = 7).
  EXPECT_LT(std::abs(dV), 1e-6);
  EXPECT_LT(std::abs(dA), 1e-6);
}

// A membrane mesh refined during a run (adaptMembraneMesh): the current shape, a prolate
// ellipsoid x = A X of the reference unit sphere, decides where (its tips); the new nodes
// are material points: an affine deformation is carried exactly, x' = A X' to round-off,
// because the same element maps (parametrised by the reference) place both (a node placed
// by another rule than the reference map would miss by O(h^2)).
TEST(Adaption, MembraneMeshNewNodesAreMaterialPoints)
{
  const SurfaceMesh sphere = makeIcosphere(2);
  const std::vector<double> X = sphere.positions();
  const Vec3 stretch(0.6, 0.6, 2.5); // volume-preserving-ish, strongly curved tips
  std::vector<double> x = X;
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] *= stretch[static_cast<Eigen::Index>(i % 3)];
  }
  SurfaceMesh current = sphere;
  current.setPositions(x);
  AdaptionOptions options;
  options.threshold = 0.5; // the tips (Q ~ 2), not the flanks (~0.2)
  const AdaptedMembraneMesh adapted = adaptMembraneMesh(current, X, options, 100000);
  ASSERT_GT(adapted.markedElements, 0);
  EXPECT_GT(adapted.current.numElements(), current.numElements());
  expectClosedAndConforming(adapted.current);
  ASSERT_EQ(adapted.reference.size(), adapted.current.positions().size());
  double worst = 0.0;
  for (std::size_t i = 0; i < adapted.reference.size(); ++i) {
    worst = std::max(worst, std::abs(adapted.current.positions()[i] -
                                     stretch[static_cast<Eigen::Index>(i % 3)] * adapted.reference[i]));
  }
  EXPECT_LT(worst, 1e-14);
  // Refined at the tips (|z| > 2 of 2.5), not on the flanks: every new node (numbered after
  // the old ones) sits where the curvature is.
  int atTips = 0, elsewhere = 0;
  for (int node = current.numNodes(); node < adapted.current.numNodes(); ++node) {
    (std::abs(adapted.current.position(node)[2]) > 1.5 ? atTips : elsewhere) += 1;
  }
  EXPECT_GT(atTips, 4 * elsewhere); // measured 440 and 24
  // The cap: no refinement that would pass maxElements.
  const AdaptedMembraneMesh capped = adaptMembraneMesh(current, X, options, current.numElements() + 1);
  EXPECT_EQ(capped.markedElements, 0);
  EXPECT_EQ(capped.current.numElements(), current.numElements());
  EXPECT_EQ(capped.reference, X);
}
