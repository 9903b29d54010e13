// Surface kinematics (thesis eqs 3.26-3.29, 3.33-3.35) and the tension kernel (eq 3.30)
// on a flat patch: uniaxial tension closed forms.
#include <capsula/elasticity/MembraneTension.hpp>
#include <capsula/elasticity/NeoHookeanLaw.hpp>
#include <capsula/elasticity/SkalakLaw.hpp>
#include <capsula/elasticity/SurfaceKinematics.hpp>
#include <capsula/mesh/ElementGeometry.hpp>
#include <capsula/mesh/Placement.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace capsula::elasticity;
using capsula::mesh::rotationAboutAxis;

const Mat3 rotation = rotationAboutAxis(Vec3(0.3, -1.0, 0.7), 1.1);

} // namespace

TEST(MembraneKinematics, DeformationGradientSolvesEqs333To335)
{
  const Vec3 Xxi(1.0, 0.2, -0.3), Xeta(0.4, 0.9, 0.5);  // reference tangents, not orthogonal
  const Vec3 xxi(0.7, -0.4, 1.1), xeta(-0.2, 1.3, 0.6); // arbitrary current tangents
  const Vec3 N = Xxi.cross(Xeta).normalized();
  const auto dual = dualTangents(Xxi, Xeta);
  EXPECT_NEAR(dual[0].dot(Xxi), 1.0, 1e-15);
  EXPECT_NEAR(dual[0].dot(Xeta), 0.0, 1e-15);
  EXPECT_NEAR(dual[1].dot(Xeta), 1.0, 1e-15);
  EXPECT_NEAR(dual[1].dot(Xxi), 0.0, 1e-15);
  const Mat3 A = surfaceDeformationGradient(xxi, xeta, dual);
  // Round-off of O(1) vectors.
  EXPECT_LT((A * Xxi - xxi).norm(), 1e-14);
  EXPECT_LT((A * Xeta - xeta).norm(), 1e-14);
  EXPECT_LT((A * N).norm(), 1e-14);
  // B has the current normal as null vector and J^2 = |x_xi x x_eta|^2 / |X_xi x X_eta|^2.
  const Mat3 B = A * A.transpose();
  const Vec3 n = xxi.cross(xeta).normalized();
  EXPECT_LT((B * n).norm(), 1e-14);
  const PrincipalStretches s = principalStretches(B, n);
  EXPECT_NEAR(s.areaRatio(), xxi.cross(xeta).norm() / Xxi.cross(Xeta).norm(), 1e-14);
  EXPECT_NEAR(s.major * s.major + s.minor * s.minor, B.trace(), 1e-14);
  EXPECT_GE(s.major, s.minor);
}

TEST(MembraneKinematics, RotateOntoCarriesOnePlaneIntoTheOther)
{
  const Vec3 from = Vec3(0.2, 0.1, 1.0).normalized(), to = Vec3(-0.3, 0.4, 0.8).normalized();
  EXPECT_LT((rotateOnto(from, from, to) - to).norm(), 1e-15);
  const Vec3 u(1.0, 2.0, -0.4), v(0.3, -0.5, 0.9);
  const Vec3 ru = rotateOnto(u, from, to), rv = rotateOnto(v, from, to);
  EXPECT_NEAR(ru.dot(rv), u.dot(v), 1e-14); // a rotation: lengths and angles kept
  EXPECT_NEAR(ru.norm(), u.norm(), 1e-14);
  EXPECT_LT((rotateOnto(u, from, from) - u).norm(), 1e-15);
  // The axis from x to is left alone (smallest rotation).
  const Vec3 axis = from.cross(to);
  EXPECT_LT((rotateOnto(axis, from, to) - axis).norm(), 1e-15);
}

TEST(MembraneKinematics, PrincipalStretchesOfARotatedDiagonalB)
{
  const double a = 1.7, b = 0.45;
  const Mat3 B = rotation * Vec3(a * a, b * b, 0.0).asDiagonal() * rotation.transpose();
  const PrincipalStretches s = principalStretches(B, rotation.col(2));
  EXPECT_NEAR(s.major, a, 1e-14);
  EXPECT_NEAR(s.minor, b, 1e-14);
  const StrainInvariants I = strainInvariants(s);
  EXPECT_NEAR(I.I1, a * a + b * b - 2.0, 1e-14);
  EXPECT_NEAR(I.I2, a * a * b * b - 1.0, 1e-14);
}

namespace {

/// A flat quadratic element (uneven midside nodes) is stretched by `stretch` along a
/// direction at 0.4 rad to its first edge and by `lateral` across, then rotated and
/// moved rigidly. Returns T at one of its nodes, the current stretch directions and
/// the principal stretches and tensions, all through the element map and eqs 3.33-3.35.
struct PatchResult {
  Mat3 tension;
  Vec3 along, across;
  PrincipalStretches stretches;
  PrincipalTensions principal;
};

PatchResult stretchFlatPatch(const MembraneLaw& law, double stretch, double lateral, int node)
{
  const capsula::mesh::ElementNodes X = {Vec3(0, 0, 0),       Vec3(1.0, 0.1, 0),   Vec3(0.2, 0.9, 0),
                                         Vec3(0.45, 0.05, 0), Vec3(0.58, 0.52, 0), Vec3(0.11, 0.495, 0)};
  const double angle = 0.4;
  const Vec3 e1(std::cos(angle), std::sin(angle), 0.0), e2(-std::sin(angle), std::cos(angle), 0.0);
  const Mat3 F =
      stretch * e1 * e1.transpose() + lateral * e2 * e2.transpose() + Vec3::UnitZ() * Vec3::UnitZ().transpose();
  capsula::mesh::ElementNodes x;
  for (int i = 0; i < 6; ++i) {
    x[i] = Vec3(0.5, -2.0, 3.0) + rotation * F * X[i];
  }
  const auto p = capsula::mesh::shapeParameters(X);
  const auto S = capsula::mesh::evaluateAtNode(X, p, node);
  const auto s = capsula::mesh::evaluateAtNode(x, p, node);
  const Mat3 A = surfaceDeformationGradient(s.tangentXi, s.tangentEta, dualTangents(S.tangentXi, S.tangentEta));
  const Mat3 B = A * A.transpose();
  PatchResult r;
  r.stretches = principalStretches(B, s.normal);
  const StrainInvariants I = strainInvariants(r.stretches);
  const EnergyDerivatives dw = law.energyDerivatives(I.I1, I.I2);
  r.tension = membraneTension(B, s.normal, r.stretches, dw);
  r.principal = principalTensions(r.stretches, dw);
  r.along = rotation * e1;
  r.across = rotation * e2;
  return r;
}

void checkUniaxial(const MembraneLaw& law, double l, double l2, double T1)
{
  for (int node = 0; node < 6; ++node) {
    const PatchResult r = stretchFlatPatch(law, l, l2, node);
    // The affine map is reproduced exactly by the quadratic element: round-off of O(1)
    // kinematics times O(10 G) tensions.
    EXPECT_NEAR(r.stretches.major, l, 1e-13);
    EXPECT_NEAR(r.stretches.minor, l2, 1e-13);
    EXPECT_LT((r.tension * r.along - T1 * r.along).norm(), 1e-12 * law.shearModulus());
    EXPECT_LT((r.tension * r.across).norm(), 1e-12 * law.shearModulus()); // T2 = 0
    EXPECT_NEAR(r.principal.major, T1, 1e-12 * law.shearModulus());
    EXPECT_NEAR(r.principal.minor, 0.0, 1e-12 * law.shearModulus());
  }
}

} // namespace

TEST(MembraneKinematics, UniaxialTensionNeoHookean)
{
  // T2 = 0 in eq 3.30: lambda2^2 = 1/(lambda1^2 lambda2^2), so lambda2 = l^(-1/2) (not
  // l^(-1/4)), and T1 = G (l^2 - l^-1) / sqrt(l) = G (l^3 - 1) / l^(3/2).
  const double G = 0.7;
  const NeoHookeanLaw law(G);
  for (double l : {1.1, 1.5, 2.5}) {
    checkUniaxial(law, l, 1.0 / std::sqrt(l), G * (l * l * l - 1.0) / std::pow(l, 1.5));
  }
}

TEST(MembraneKinematics, UniaxialTensionSkalak)
{
  // T2 = 0: lambda2^2 - 1 + C lambda1^2 (lambda1^2 lambda2^2 - 1) = 0, so
  // lambda2^2 = (1 + C l^2) / (1 + C l^4); T1 = G (l/lambda2) [l^2 - 1 + C lambda2^2 (l^2 lambda2^2
  // - 1)].
  const double G = 0.7;
  for (double C : {0.0, 1.0, 10.0}) {
    const SkalakLaw law(G, C);
    for (double l : {1.1, 1.5, 2.5}) {
      const double l2 = std::sqrt((1.0 + C * l * l) / (1.0 + C * l * l * l * l));
      const double T1 = G * (l / l2) * (l * l - 1.0 + C * l2 * l2 * (l * l * l2 * l2 - 1.0));
      checkUniaxial(law, l, l2, T1);
    }
  }
}
