// Membrane laws (thesis eqs 3.29-3.32): energies, derivatives, tensions, validation,
// factory.
#include <capsula/core/Error.hpp>
#include <capsula/elasticity/MembraneLawRegistry.hpp>
#include <capsula/elasticity/MembraneTension.hpp>
#include <capsula/elasticity/NeoHookeanLaw.hpp>
#include <capsula/elasticity/PrincipalStiffness.hpp>
#include <capsula/elasticity/SkalakLaw.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace capsula::elasticity;

constexpr double G = 0.7;
constexpr double C = 2.5;

/// The laws as printed in the thesis, in stretches (eq 3.31 with the constant that makes
/// w vanish at rest, eq 3.32).
double printedNeoHookean(double l1, double l2)
{
  return 0.5 * G * (l1 * l1 + l2 * l2 + 1.0 / (l1 * l1 * l2 * l2) - 3.0);
}
double printedSkalak(double l1, double l2)
{
  const double a = l1 * l1 - 1.0, b = l2 * l2 - 1.0, c = l1 * l1 * l2 * l2 - 1.0;
  return 0.25 * G * (a * a + b * b + C * c * c);
}

double energyInStretches(const MembraneLaw& law, double l1, double l2)
{
  const StrainInvariants I = strainInvariants({l1, l2});
  return law.energyDensity(I.I1, I.I2);
}

const std::vector<double> stretches = {0.6, 0.85, 1.0, 1.1, 1.4, 2.0};

} // namespace

TEST(MembraneLaw, EnergiesVanishAtRestAndEqualThePrintedStretchForms)
{
  const NeoHookeanLaw neo(G);
  const SkalakLaw skalak(G, C);
  EXPECT_EQ(neo.energyDensity(0.0, 0.0), 0.0);
  EXPECT_EQ(skalak.energyDensity(0.0, 0.0), 0.0);
  for (double l1 : stretches) {
    for (double l2 : stretches) {
      // Same polynomial/rational expression regrouped: round-off of O(w + G).
      EXPECT_NEAR(energyInStretches(neo, l1, l2), printedNeoHookean(l1, l2), 1e-14 * 10 * G);
      EXPECT_NEAR(energyInStretches(skalak, l1, l2), printedSkalak(l1, l2), 1e-14 * 100 * G);
    }
  }
}

TEST(MembraneLaw, DerivativesMatchCentralDifferences)
{
  const NeoHookeanLaw neo(G);
  const SkalakLaw skalak(G, C);
  const double h = 1e-5;
  for (const MembraneLaw* law : std::vector<const MembraneLaw*>{&neo, &skalak}) {
    for (double I1 : {-0.3, 0.0, 0.4, 1.5}) {
      for (double I2 : {-0.5, 0.0, 0.3, 2.0}) {
        const EnergyDerivatives d = law->energyDerivatives(I1, I2);
        const double d1 = (law->energyDensity(I1 + h, I2) - law->energyDensity(I1 - h, I2)) / (2 * h);
        const double d2 = (law->energyDensity(I1, I2 + h) - law->energyDensity(I1, I2 - h)) / (2 * h);
        // Truncation h^2 w''' / 6 ~ 1e-10 G (neo-Hookean w''' = 3 G/(I2+1)^4 <= 48 G here);
        // round-off eps w / h ~ 1e-11 G.
        EXPECT_NEAR(d.dI1, d1, 1e-8 * G) << law->name();
        EXPECT_NEAR(d.dI2, d2, 1e-8 * G) << law->name();
      }
    }
  }
}

TEST(MembraneLaw, PrincipalTensionsAreTheStretchDerivativesOfTheEnergy)
{
  // T_1 = (1/lambda2) dw/dlambda1: eq 3.30 is the law's tension, not just a formula.
  const NeoHookeanLaw neo(G);
  const SkalakLaw skalak(G, C);
  const double h = 1e-6;
  for (const MembraneLaw* law : std::vector<const MembraneLaw*>{&neo, &skalak}) {
    for (double l1 : stretches) {
      for (double l2 : stretches) {
        if (l1 < l2) {
          continue;
        }
        const StrainInvariants I = strainInvariants({l1, l2});
        const PrincipalTensions T = principalTensions({l1, l2}, law->energyDerivatives(I.I1, I.I2));
        const double t1 = (energyInStretches(*law, l1 + h, l2) - energyInStretches(*law, l1 - h, l2)) / (2 * h) / l2;
        const double t2 = (energyInStretches(*law, l1, l2 + h) - energyInStretches(*law, l1, l2 - h)) / (2 * h) / l1;
        // Which of t1, t2 is larger depends on the law; compare as sorted pairs.
        // Truncation h^2 w'''/6 < 1e-10 G, round-off eps w/h < 1e-8 G (w < 50 G).
        EXPECT_NEAR(T.major, std::max(t1, t2), 2e-8 * G) << law->name() << " " << l1 << " " << l2;
        EXPECT_NEAR(T.minor, std::min(t1, t2), 2e-8 * G) << law->name() << " " << l1 << " " << l2;
      }
    }
  }
}

TEST(MembraneLaw, PrincipalStiffnessIsTheSecondStretchDerivativeOfTheEnergy)
{
  // k_1 = d2w/dlambda1^2 at fixed lambda2, for both laws and for Skalak with the small C of
  // the thesis's soft cells, on the grid of stretches both ways round.
  const NeoHookeanLaw neo(G);
  const SkalakLaw skalak(G, C);
  const SkalakLaw soft(G, 0.5);
  const double h = 1e-4;
  for (const MembraneLaw* law : std::vector<const MembraneLaw*>{&neo, &skalak, &soft}) {
    for (double l1 : stretches) {
      for (double l2 : stretches) {
        const StrainInvariants I = strainInvariants({l1, l2});
        const double k =
            principalStiffness(l1, l2, law->energyDerivatives(I.I1, I.I2), law->energySecondDerivatives(I.I1, I.I2));
        const double fd = (energyInStretches(*law, l1 + h, l2) - 2.0 * energyInStretches(*law, l1, l2) +
                           energyInStretches(*law, l1 - h, l2)) /
                          (h * h);
        // Truncation h^2 w/12 <= 2e-7 G (w <= 246 G on this grid); round-off
        // 4 eps w / h^2 <= 1.3e-5 G where w is largest (145 G, at k = 481 G). A wrong
        // factor in any of the four terms is O(G).
        EXPECT_NEAR(k, fd, 2e-5 * std::max(G, std::abs(k))) << law->name() << " " << l1 << " " << l2;
      }
    }
  }
}

TEST(MembraneLaw, SkalakSoftensInCompressionAndNeoHookeanDoesNot)
{
  // Skalak: k_1 = G [3 lambda1^2 (1 + C lambda2^4) - (1 + C lambda2^2)], zero at
  // lambda1^2 = (1 + C lambda2^2) / (3 (1 + C lambda2^4)): 1/sqrt(3) at lambda2 = 1 for every C.
  for (double c : {0.0, 0.5, 2.5, 10.0}) {
    const SkalakLaw law(G, c);
    for (double l2 : {0.8, 1.0, 1.3}) {
      const double limit = std::sqrt((1.0 + c * l2 * l2) / (3.0 * (1.0 + c * std::pow(l2, 4.0))));
      if (l2 == 1.0) {
        EXPECT_NEAR(limit, 1.0 / std::sqrt(3.0), 1e-15);
      }
      // 1% either side of the limit the sign flips (k there is -+0.02 (1 + C lambda2^2) G,
      // far above round-off); the least of the two directions sees it.
      EXPECT_LT(leastPrincipalStiffness(law, {l2, 0.99 * limit}), 0.0) << "C = " << c << " lambda2 = " << l2;
      const StrainInvariants below = strainInvariants({l2, 0.99 * limit});
      const StrainInvariants above = strainInvariants({l2, 1.01 * limit});
      EXPECT_LT(principalStiffness(0.99 * limit, l2, law.energyDerivatives(below.I1, below.I2),
                                   law.energySecondDerivatives(below.I1, below.I2)),
                0.0);
      EXPECT_GT(principalStiffness(1.01 * limit, l2, law.energyDerivatives(above.I1, above.I2),
                                   law.energySecondDerivatives(above.I1, above.I2)),
                0.0);
    }
    // At rest k = G [3 (1 + C) - (1 + C)] = 2 G (1 + C) in both directions.
    EXPECT_NEAR(leastPrincipalStiffness(law, {1.0, 1.0}), 2.0 * G * (1.0 + c), 1e-14 * G * (1.0 + c));
  }
  // Neo-Hookean: k_1 = G (1 + 3 / (lambda1^4 lambda2^2)) > G at every stretch.
  const NeoHookeanLaw neo(G);
  for (double l1 : {0.2, 0.577, 1.0, 2.0}) {
    for (double l2 : {0.5, 1.0, 2.0}) {
      const StrainInvariants I = strainInvariants({l1, l2});
      const double k =
          principalStiffness(l1, l2, neo.energyDerivatives(I.I1, I.I2), neo.energySecondDerivatives(I.I1, I.I2));
      EXPECT_NEAR(k, G * (1.0 + 3.0 / (std::pow(l1, 4.0) * l2 * l2)), 1e-12 * k) << l1 << " " << l2;
    }
  }
}

TEST(MembraneLaw, IsotropicTensionClosedForms)
{
  // lambda1 = lambda2 = s: T = (1/s) dw/dlambda1. Neo-Hookean: w = G/2 (2 s^2 + s^-4 - 3)
  // per direction gives G (s - s^-5)/s = G (1 - s^-6). Skalak: G [(s^2-1) + C s^2 (s^4-1)].
  const NeoHookeanLaw neo(G);
  const SkalakLaw skalak(G, C);
  for (double s : {0.8, 1.0, 1.025, 1.5}) {
    const StrainInvariants I = strainInvariants({s, s});
    const PrincipalTensions n = principalTensions({s, s}, neo.energyDerivatives(I.I1, I.I2));
    const PrincipalTensions k = principalTensions({s, s}, skalak.energyDerivatives(I.I1, I.I2));
    const double neoT = G * (1.0 - std::pow(s, -6.0));
    const double skalakT = G * ((s * s - 1.0) + C * s * s * (std::pow(s, 4.0) - 1.0));
    // Round-off of O(10 G) quantities.
    EXPECT_NEAR(n.major, neoT, 1e-14 * 10 * G);
    EXPECT_NEAR(n.minor, neoT, 1e-14 * 10 * G);
    EXPECT_NEAR(k.major, skalakT, 1e-14 * 100 * G);
    EXPECT_NEAR(k.minor, skalakT, 1e-14 * 100 * G);
  }
}

TEST(MembraneLaw, RejectsBadModuliNamingThem)
{
  const double nan = std::nan("");
  for (double bad : {0.0, -1.5, nan, HUGE_VAL}) {
    try {
      NeoHookeanLaw law(bad);
      ADD_FAILURE() << "NeoHookean accepted G = " << bad;
    } catch (const capsula::core::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("shear modulus G"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("NeoHookean"), std::string::npos) << e.what();
    }
    EXPECT_THROW(SkalakLaw(bad, 1.0), capsula::core::InputError);
  }
  for (double bad : {-0.1, nan, HUGE_VAL}) {
    try {
      SkalakLaw law(1.0, bad);
      ADD_FAILURE() << "Skalak accepted C = " << bad;
    } catch (const capsula::core::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("area-dilation ratio C"), std::string::npos) << e.what();
    }
  }
  try {
    SkalakLaw law(-2.0, 1.0);
    ADD_FAILURE() << "Skalak accepted G = -2";
  } catch (const capsula::core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("-2"), std::string::npos) << e.what(); // the value
  }
  EXPECT_NO_THROW(SkalakLaw(1.0, 0.0)); // C = 0: no extra area resistance, still valid
}

TEST(MembraneLaw, RegistryBuildsLawsByName)
{
  const MembraneLawRegistry laws = builtInMembraneLaws();
  EXPECT_EQ(laws.names(), (std::vector<std::string>{"NeoHookean", "Skalak"}));
  Teuchos::ParameterList skalakKeys;
  skalakKeys.set("Area dilation C", C);
  const auto neo = laws.create("NeoHookean", G);
  const auto skalak = laws.create("Skalak", G, skalakKeys);
  EXPECT_EQ(neo->name(), "NeoHookean");
  EXPECT_EQ(skalak->name(), "Skalak");
  EXPECT_EQ(neo->shearModulus(), G);
  EXPECT_EQ(skalak->energyDensity(0.3, 0.2), SkalakLaw(G, C).energyDensity(0.3, 0.2));
  EXPECT_EQ(neo->energyDensity(0.3, 0.2), NeoHookeanLaw(G).energyDensity(0.3, 0.2));
  // Skalak declares its own key; left out, it takes the declared default.
  EXPECT_EQ(laws.info("Skalak").validParameters->get<double>("Area dilation C"), 2.5);
  EXPECT_EQ(laws.create("Skalak", G)->energyDensity(0.3, 0.2), SkalakLaw(G, 2.5).energyDensity(0.3, 0.2));
  EXPECT_TRUE(laws.info("NeoHookean").validParameters.is_null());
  try {
    laws.create("Hookean", G);
    ADD_FAILURE() << "unknown law accepted";
  } catch (const capsula::core::InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("Hookean'"), std::string::npos) << what;
    EXPECT_NE(what.find("NeoHookean, Skalak"), std::string::npos) << what;
    EXPECT_NE(what.find("Did you mean 'NeoHookean'?"), std::string::npos) << what;
  }
  skalakKeys.set("Area dilation C", -1.0);
  EXPECT_THROW(laws.create("Skalak", G, skalakKeys), capsula::core::InputError);
}
