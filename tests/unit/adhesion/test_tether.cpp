// The tether (one permanent bond to an anchor on the wall): its deck keys and their
// refusals, where it holds the membrane (the farthest material point along a direction, the
// patch around it), its spring force for a known geometry, and its nodal forces, whose sum
// and torque are the spring's.
#include <capsula/adhesion/BondSpring.hpp>
#include <capsula/adhesion/Tether.hpp>
#include <capsula/adhesion/TetherPlacement.hpp>
#include <capsula/core/Deck.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>
#include <capsula/mesh/ElementGeometry.hpp>
#include <capsula/mesh/Icosphere.hpp>
#include <capsula/quadrature/TriangleRule.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace adhesion = capsula::adhesion;
namespace core = capsula::core;
namespace mesh = capsula::mesh;
using mesh::Vec3;

namespace {

// The "Tether" sublist of `xml`, validated against the declared keys.
Teuchos::RCP<Teuchos::ParameterList> tetherDeck(const std::string& xml)
{
  Teuchos::ParameterList valid("Capsula");
  adhesion::declareTetherParameters(core::declareSublist(valid, "Tether", "The tether"));
  auto deck = core::readDeckFromString("<ParameterList name=\"Capsula\"><ParameterList name=\"Tether\">" + xml +
                                           "</ParameterList></ParameterList>",
                                       "deck.xml");
  core::validateDeck(*deck, valid, "deck.xml");
  return deck;
}

// The message of the InputError that reading the tether of `xml` throws ("" if none).
std::string tetherRefusal(const std::string& xml)
{
  try {
    adhesion::readTetherParameters(tetherDeck(xml)->sublist("Tether"));
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "";
}

std::string arrayParameter(const std::string& key, const std::string& value)
{
  return "<Parameter name=\"" + key + "\" type=\"Array(double)\" value=\"" + value + "\"/>";
}

// A unit sphere (icosphere of `level`) centred at (0, height, 0).
mesh::SurfaceMesh sphereAt(int level, double height)
{
  mesh::SurfaceMesh m = mesh::makeIcosphere(level);
  for (int n = 0; n < m.numNodes(); ++n) {
    m.setPosition(n, m.position(n) + Vec3(0.0, height, 0.0));
  }
  return m;
}

// The unit icosphere stretched into a tilted egg above the wall: curved, without symmetry.
mesh::SurfaceMesh tetheredEgg(int level)
{
  mesh::SurfaceMesh m = mesh::makeIcosphere(level);
  for (int n = 0; n < m.numNodes(); ++n) {
    const Vec3 x = m.position(n);
    m.setPosition(n, Vec3(1.3 * x[0] + 0.2 * x[1] * x[1] + 0.1 * x[1], x[1] + 1.2, 0.8 * x[2] + 0.3));
  }
  return m;
}

// The largest x . d over a fine lattice of every element's parametric triangle: what the
// exact search must match or beat.
double sampledMaximum(const mesh::SurfaceMesh& m, const adhesion::ReceptorSet& points, const Vec3& d)
{
  double largest = -1e300;
  const int n = 40;
  for (int e = 0; e < m.numElements(); ++e) {
    const mesh::ElementNodes x = m.elementNodes(e);
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; i + j <= n; ++j) {
        const double value = mesh::surfacePosition(x, points.shapeParameters(e), double(i) / n, double(j) / n).dot(d);
        largest = std::max(largest, value);
      }
    }
  }
  return largest;
}

adhesion::TetherSettings enabledTether()
{
  adhesion::TetherSettings s;
  s.enabled = true;
  return s;
}

} // namespace

TEST(TetherParameters, DefaultsAreTheDocumentedOnes)
{
  const auto s = adhesion::readTetherParameters(tetherDeck("")->sublist("Tether"));
  EXPECT_FALSE(s.enabled);
  EXPECT_EQ(s.cell, 0);
  EXPECT_EQ(s.polarAngle, 0.0);
  EXPECT_EQ(s.springConstant, 100.0);
  EXPECT_EQ(s.patchRadius, 0.0);
  EXPECT_FALSE(s.anchor.has_value());     // below the attachment point
  EXPECT_FALSE(s.restLength.has_value()); // the length at t = 0
  // The default direction is straight down; 90 degrees at azimuth 180 points upstream.
  EXPECT_EQ(s.direction(), Vec3(0.0, -1.0, 0.0));
  adhesion::TetherSettings upstream;
  upstream.polarAngle = 90.0;
  upstream.azimuth = 180.0;
  EXPECT_LT((upstream.direction() - Vec3(-1.0, 0.0, 0.0)).norm(), 1e-15);
}

TEST(TetherParameters, ReadsTheAnchorAndRestLength)
{
  const auto s = adhesion::readTetherParameters(
      tetherDeck(arrayParameter("Anchor", "{-0.5, 0, 0.25}") + arrayParameter("Rest length", "{0.1}"))
          ->sublist("Tether"));
  ASSERT_TRUE(s.anchor && s.restLength);
  EXPECT_EQ(*s.anchor, Vec3(-0.5, 0.0, 0.25));
  EXPECT_EQ(*s.restLength, 0.1);
}

TEST(TetherParameters, RefusesBadInputNamingTheKey)
{
  const std::string on = "<Parameter name=\"Enabled\" type=\"bool\" value=\"true\"/>";
  EXPECT_NE(tetherRefusal(on + arrayParameter("Anchor", "{0, 0.2, 0}"))
                .find("'Tether/Anchor' = {0, 0.2, 0} lies off "
                      "the wall"),
            std::string::npos);
  EXPECT_NE(tetherRefusal(on + arrayParameter("Anchor", "{0, 0}")).find("'Tether/Anchor'"), std::string::npos);
  EXPECT_NE(tetherRefusal(on + arrayParameter("Rest length", "{0.1, 0.2}")).find("'Tether/Rest length'"),
            std::string::npos);
  // The validators: a negative spring constant, rest length or radius, an angle past 180.
  for (const std::string& bad :
       std::vector<std::string>{"<Parameter name=\"Spring constant\" type=\"double\" value=\"-1\"/>",
                                "<Parameter name=\"Patch radius\" type=\"double\" value=\"-0.1\"/>",
                                "<Parameter name=\"Polar angle\" type=\"double\" value=\"200\"/>",
                                arrayParameter("Rest length", "{-0.1}")}) {
    const std::string message = tetherRefusal(on + bad);
    EXPECT_NE(message.find("'Tether/"), std::string::npos) << bad;
    EXPECT_NE(message.find("invalid"), std::string::npos) << message;
  }
  // A spring constant of 0 is refused only with the tether on.
  const std::string zero = "<Parameter name=\"Spring constant\" type=\"double\" value=\"0\"/>";
  EXPECT_NE(tetherRefusal(on + zero).find("'Tether/Spring constant' = 0 with the tether enabled"), std::string::npos);
  EXPECT_EQ(tetherRefusal(zero), "");
}

TEST(BondSpring, PullsTowardsTheAnchorWhenStretchedAndPushesWhenCompressed)
{
  // A spring from (0.3, 0.4, 0) to the origin: length 0.5 along (0.6, 0.8, 0).
  const Vec3 x(0.3, 0.4, 0.0), anchor = Vec3::Zero();
  const Vec3 stretched = adhesion::springForce(x, anchor, 10.0, 0.2); // 10 x 0.3 = 3 towards the anchor
  EXPECT_LT((stretched - Vec3(-1.8, -2.4, 0.0)).norm(), 1e-14);
  const Vec3 compressed = adhesion::springForce(x, anchor, 10.0, 0.7); // 10 x 0.2 = 2 away from it
  EXPECT_LT((compressed - Vec3(1.2, 1.6, 0.0)).norm(), 1e-14);
}

TEST(TetherPlacement, FindsTheFarthestMaterialPointExactly)
{
  // On a sphere the point farthest along d is the point at d from the centre; on the egg the
  // exact per-element search must not be beaten by a 40 x 40 lattice of every element.
  const mesh::SurfaceMesh sphere = sphereAt(2, 1.1);
  const adhesion::ReceptorSet onSphere(sphere, sphere.positions(), std::vector<adhesion::Receptor>{});
  const Vec3 down(0.0, -1.0, 0.0);
  const adhesion::Receptor lowest = adhesion::farthestMaterialPoint(sphere, sphere.positionData(), onSphere, down);
  const Vec3 x = mesh::surfacePosition(sphere.elementNodes(lowest.element), onSphere.shapeParameters(lowest.element),
                                       lowest.xi, lowest.eta);
  // The icosphere has a node at (0, -1, 0); the quadratic surface around it stays within the
  // chord height of a level-2 element (~2e-3) of the sphere.
  EXPECT_LT((x - Vec3(0.0, 0.1, 0.0)).norm(), 2e-3);
  EXPECT_GE(x.dot(down), sampledMaximum(sphere, onSphere, down) - 1e-13);
  const double theta = 60.0 * M_PI / 180.0;
  const Vec3 tilted(std::sin(theta), -std::cos(theta), 0.0);
  const adhesion::Receptor side = adhesion::farthestMaterialPoint(sphere, sphere.positionData(), onSphere, tilted);
  const Vec3 y = mesh::surfacePosition(sphere.elementNodes(side.element), onSphere.shapeParameters(side.element),
                                       side.xi, side.eta);
  EXPECT_LT((y - Vec3(0.0, 1.1, 0.0) - tilted).norm(), 2e-2); // within a few chord heights: a 5-degree error fails

  const mesh::SurfaceMesh egg = tetheredEgg(2);
  const adhesion::ReceptorSet onEgg(egg, mesh::makeIcosphere(2).positions(), std::vector<adhesion::Receptor>{});
  for (const Vec3& d : {down, tilted, Vec3(Vec3(-0.3, -1.0, 0.5).normalized())}) {
    const adhesion::Receptor p = adhesion::farthestMaterialPoint(egg, egg.positionData(), onEgg, d);
    const double found =
        mesh::surfacePosition(egg.elementNodes(p.element), onEgg.shapeParameters(p.element), p.xi, p.eta).dot(d);
    // The lattice's points are points of the surface: the maximum is at least as large, and
    // close to the lattice's best (spacing 1/40 of an element: 1e-4 of a curvature ~1 surface).
    EXPECT_GE(found, sampledMaximum(egg, onEgg, d) - 1e-13) << d.transpose();
    EXPECT_LT(found, sampledMaximum(egg, onEgg, d) + 1e-4) << d.transpose();
  }
}

TEST(Tether, ForceOfAKnownGeometry)
{
  // A unit sphere 0.1 a above the wall, tethered at its lowest point (0, 0.1, 0) to the anchor
  // (-0.3, 0, 0.4) with rest length 0.2 and sigma = 50: L = sqrt(0.09 + 0.01 + 0.16), F =
  // 50 (L - 0.2) towards the anchor.
  const mesh::SurfaceMesh sphere = sphereAt(2, 1.1);
  adhesion::TetherSettings s = enabledTether();
  s.springConstant = 50.0;
  s.anchor = Vec3(-0.3, 0.0, 0.4);
  s.restLength = 0.2;
  const adhesion::Tether tether(s, sphere, sphere.positionData(), sphere.positions());
  const adhesion::TetherState state = tether.state(sphere, sphere.positionData());
  ASSERT_LT((state.attachment - Vec3(0.0, 0.1, 0.0)).norm(), 2e-3);
  const Vec3 towards = (s.anchor.value() - state.attachment).normalized();
  EXPECT_LT((state.force.normalized() - towards).norm(), 1e-14);
  EXPECT_NEAR(state.force.norm(), 50.0 * ((state.attachment - *s.anchor).norm() - 0.2), 1e-13);
  // Against the nominal geometry, within the attachment's chord-height error (2e-3 x sigma).
  EXPECT_NEAR(state.force.norm(), 50.0 * (std::sqrt(0.26) - 0.2), 0.1);
  EXPECT_LT(state.force[0], 0.0); // upstream, down, and towards +z
  EXPECT_LT(state.force[1], 0.0);
  EXPECT_GT(state.force[2], 0.0);
  EXPECT_NEAR(state.inclinationDegrees, std::atan2(0.1, 0.5) * 180.0 / M_PI, 0.3);
  EXPECT_NEAR(adhesion::pivotAngleDegrees(*s.anchor, Vec3(0.8, 1.1, 0.0)), 45.0, 1e-12);
}

TEST(Tether, DefaultAnchorAndRestLengthStartUnstressed)
{
  const mesh::SurfaceMesh sphere = sphereAt(1, 1.05);
  const adhesion::Tether tether(enabledTether(), sphere, sphere.positionData(), sphere.positions());
  const Vec3 x = tether.attachment(sphere, sphere.positionData());
  EXPECT_EQ(tether.anchor(), Vec3(x[0], 0.0, x[2])); // straight below
  EXPECT_EQ(tether.restLength(), x[1]);
  EXPECT_EQ(tether.state(sphere, sphere.positionData()).force.norm(), 0.0);
  EXPECT_NEAR(tether.state(sphere, sphere.positionData()).inclinationDegrees, 90.0, 1e-12);
  // Lifted by 0.01: a pull of sigma x 0.01 = 1 straight down.
  std::vector<double> lifted = sphere.positions();
  for (std::size_t i = 1; i < lifted.size(); i += 3) {
    lifted[i] += 0.01;
  }
  EXPECT_LT((tether.state(sphere, lifted.data()).force - Vec3(0.0, -1.0, 0.0)).norm(), 1e-12);
}

TEST(Tether, NodalForcesCarryTheSpringsForceAndTorque)
{
  // A point tether and a patch of radius 0.3 on the egg, deformed away from where they were
  // placed (not a rigid motion), the spring stretched to an anchor off to the side.
  const mesh::SurfaceMesh egg = tetheredEgg(2);
  const std::vector<double> reference = mesh::makeIcosphere(2).positions();
  std::vector<double> x = egg.positions();
  for (std::size_t i = 0; i < x.size(); i += 3) {
    x[i] += 0.05 * std::sin(3.0 * x[i + 1]);
    x[i + 1] += 0.2;
  }
  for (const double radius : {0.0, 0.3}) {
    adhesion::TetherSettings s = enabledTether();
    s.patchRadius = radius;
    s.anchor = Vec3(0.4, 0.0, -0.2);
    s.restLength = 0.05;
    s.springConstant = 30.0;
    const adhesion::Tether tether(s, egg, egg.positionData(), reference);
    double total = 0.0;
    for (const double w : tether.weights()) {
      total += w;
    }
    EXPECT_NEAR(total, 1.0, 1e-14);
    if (radius > 0.0) {
      EXPECT_GT(tether.points().size(), 20); // the patch covers several elements of a level-2 mesh
    }
    std::vector<double> nodal(x.size(), 0.0);
    const Vec3 force = tether.addNodalForces(egg, x.data(), nodal.data());
    const adhesion::TetherState state = tether.state(egg, x.data());
    EXPECT_LT((force - state.force).norm(), 1e-15 * force.norm());
    const Vec3 about(0.4, -0.7, 1.1);
    Vec3 nodalForce = Vec3::Zero(), nodalTorque = Vec3::Zero();
    for (int n = 0; n < egg.numNodes(); ++n) {
      nodalForce += mesh::nodeAt(nodal.data(), n);
      nodalTorque += (mesh::nodeAt(x.data(), n) - about).cross(mesh::nodeAt(nodal.data(), n));
    }
    // Sums of ~6 x (patch points) products of O(|F|) numbers: round-off ~1e-14 |F|. A missing
    // shape function or weight would be off by ~0.1 |F|.
    const double scale = force.norm();
    ASSERT_GT(scale, 1.0);
    EXPECT_LT((nodalForce - force).norm(), 1e-13 * scale) << radius;
    EXPECT_LT((nodalTorque - (state.attachment - about).cross(force)).norm(), 1e-13 * scale * 3.0) << radius;
  }
}

TEST(TetherPlacement, PatchWeightsAreAreaTimesTheBump)
{
  // Every quadrature point within rho of the centre and no other, each weighted by its area
  // share times (1 - r^2/rho^2)^2, normalised.
  const mesh::SurfaceMesh sphere = sphereAt(2, 1.1);
  const adhesion::ReceptorSet points(sphere, sphere.positions(), std::vector<adhesion::Receptor>{});
  const adhesion::Receptor centre =
      adhesion::farthestMaterialPoint(sphere, sphere.positionData(), points, Vec3(0.0, -1.0, 0.0));
  const double rho = 0.4;
  const adhesion::WeightedPoints patch = adhesion::materialPatch(sphere, sphere.positionData(), points, centre, rho);
  const Vec3 x0 = mesh::surfacePosition(sphere.elementNodes(centre.element), points.shapeParameters(centre.element),
                                        centre.xi, centre.eta);
  const capsula::quadrature::TriangleRule& rule = capsula::quadrature::triangleRule(7);
  std::vector<double> expected;
  double total = 0.0;
  for (int e = 0; e < sphere.numElements(); ++e) {
    for (int q = 0; q < rule.size(); ++q) {
      const auto k = static_cast<std::size_t>(q);
      const mesh::SurfacePoint p =
          mesh::evaluateSurfacePoint(sphere.elementNodes(e), points.shapeParameters(e), rule.xi[k], rule.eta[k]);
      const double r = (p.position - x0).norm() / rho;
      if (r < 1.0) {
        expected.push_back(rule.weight[k] * p.metric * std::pow(1.0 - r * r, 2));
        total += expected.back();
      }
    }
  }
  ASSERT_EQ(patch.weights.size(), expected.size());
  ASSERT_GT(expected.size(), 30u); // a level-2 patch of radius 0.4 spans several elements
  for (std::size_t i = 0; i < expected.size(); ++i) {
    // The same products in the same order, normalised: round-off of one division.
    EXPECT_NEAR(patch.weights[i], expected[i] / total, 1e-15) << i;
  }
}

TEST(Tether, RefusesAPatchThatHoldsTooFewPoints)
{
  // Level 1: quadrature points ~0.2 apart; a radius of 0.02 reaches at most one of them.
  const mesh::SurfaceMesh sphere = sphereAt(1, 1.05);
  adhesion::TetherSettings s = enabledTether();
  s.patchRadius = 0.02;
  try {
    adhesion::Tether(s, sphere, sphere.positionData(), sphere.positions());
    FAIL() << "a patch of one point was accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'Tether/Patch radius' = 0.02"), std::string::npos) << e.what();
  }
}
