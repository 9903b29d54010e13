#include <capsula/quadrature/TriangleRule.hpp>

#include <capsula/core/Error.hpp>

#include <algorithm>
#include <sstream>

namespace capsula::quadrature {
namespace {

// A symmetric rule is a union of orbits of the triangle's symmetry group, given in
// barycentric coordinates (l1, l2, l3) with per-point weights that sum to 1 over the rule
// (the tables' convention); they are halved when expanded, so they sum to the area 1/2.
enum class OrbitKind {
  Centroid,    // (1/3, 1/3, 1/3): 1 point
  TwoEqual,    // (a, a, 1 - 2a): 3 points
  AllDistinct, // (a, b, 1 - a - b): 6 points
};

struct Orbit {
  OrbitKind kind;
  double a;
  double b;
  double weight;
};

struct SymmetricRule {
  int degree;
  std::vector<Orbit> orbits;
};

// Literature values (Dunavant 1985; the 9-point rule is Strang & Fix 1973, as tabulated
// by Pozrikidis 2002), refined to 20 digits by solving the symmetric moment equations in
// 50-digit arithmetic; each matched the printed 15 digits to 5e-16. The unit tests check
// every monomial up to the stated degree and that degree + 1 fails.
std::vector<SymmetricRule> symmetricRules()
{
  using K = OrbitKind;
  return {
      {1, {{K::Centroid, 0, 0, 1.0}}},
      {2, {{K::TwoEqual, 1.0 / 6.0, 0, 1.0 / 3.0}}},
      {3, {{K::Centroid, 0, 0, -27.0 / 48.0}, {K::TwoEqual, 0.2, 0, 25.0 / 48.0}}},
      {4,
       {{K::TwoEqual, 0.44594849091596488632, 0, 0.2233815896780114657},
        {K::TwoEqual, 0.09157621350977074346, 0, 0.10995174365532186764}}},
      {5,
       {{K::Centroid, 0, 0, 0.225},
        {K::TwoEqual, 0.47014206410511508977, 0, 0.13239415278850618074},
        {K::TwoEqual, 0.1012865073234563388, 0, 0.1259391805448271526}}},
      {5, // 9 points (Strang & Fix; the thesis's N_Q = 9): degree 5, as the 7-point rule
       {{K::TwoEqual, 0.43752524838338386733, 0, 0.20595050476088660301},
        {K::AllDistinct, 0.79711265186007080142, 0.16540992738984142292, 0.063691414286223365161}}},
      {6,
       {{K::TwoEqual, 0.24928674517091042129, 0, 0.11678627572637936603},
        {K::TwoEqual, 0.06308901449150222834, 0, 0.050844906370206816921},
        {K::AllDistinct, 0.053145049844816947353, 0.31035245103378440542, 0.082851075618373575194}}},
      {7,
       {{K::Centroid, 0, 0, -0.14957004446768175063},
        {K::TwoEqual, 0.26034596607903982693, 0, 0.17561525743320781175},
        {K::TwoEqual, 0.065130102902215811538, 0, 0.05334723560883849127},
        {K::AllDistinct, 0.048690315425316411793, 0.31286549600487386141, 0.07711376089025714026}}},
      {8,
       {{K::Centroid, 0, 0, 0.14431560767778716825},
        {K::TwoEqual, 0.45929258829272315603, 0, 0.095091634267284624794},
        {K::TwoEqual, 0.17056930775176020662, 0, 0.10321737053471825028},
        {K::TwoEqual, 0.050547228317030975458, 0, 0.032458497623198080311},
        {K::AllDistinct, 0.0083947774099576053372, 0.26311282963463811342, 0.027230314174434994265}}},
      {9,
       {{K::Centroid, 0, 0, 0.097135796282798833819},
        {K::TwoEqual, 0.48968251919873762778, 0, 0.031334700227139070537},
        {K::TwoEqual, 0.43708959149293663727, 0, 0.077827541004774279317},
        {K::TwoEqual, 0.18820353561903273024, 0, 0.079647738927210253033},
        {K::TwoEqual, 0.044729513394452709865, 0, 0.025577675658698031262},
        {K::AllDistinct, 0.036838412054736283635, 0.22196298916076569568, 0.043283539377289377289}}},
  };
}

TriangleRule expand(const SymmetricRule& symmetric)
{
  TriangleRule rule;
  rule.degree = symmetric.degree;
  auto add = [&rule](double xi, double eta, double weight) {
    rule.xi.push_back(xi);
    rule.eta.push_back(eta);
    rule.weight.push_back(0.5 * weight);
  };
  for (const Orbit& orbit : symmetric.orbits) {
    switch (orbit.kind) {
    case OrbitKind::Centroid:
      add(1.0 / 3.0, 1.0 / 3.0, orbit.weight);
      break;
    case OrbitKind::TwoEqual: {
      const double c = 1.0 - 2.0 * orbit.a;
      add(orbit.a, orbit.a, orbit.weight);
      add(orbit.a, c, orbit.weight);
      add(c, orbit.a, orbit.weight);
      break;
    }
    case OrbitKind::AllDistinct: {
      const double a = orbit.a, b = orbit.b, c = 1.0 - orbit.a - orbit.b;
      add(a, b, orbit.weight);
      add(b, a, orbit.weight);
      add(a, c, orbit.weight);
      add(c, a, orbit.weight);
      add(b, c, orbit.weight);
      add(c, b, orbit.weight);
      break;
    }
    }
  }
  return rule;
}

const std::vector<TriangleRule>& allTriangleRules()
{
  // Immutable once built (thread-safe initialisation of a function-local static).
  static const std::vector<TriangleRule> rules = [] {
    std::vector<TriangleRule> expanded;
    for (const SymmetricRule& symmetric : symmetricRules()) {
      expanded.push_back(expand(symmetric));
    }
    return expanded;
  }();
  return rules;
}

} // namespace

std::vector<int> supportedTriangleRules()
{
  std::vector<int> counts;
  for (const TriangleRule& rule : allTriangleRules()) {
    counts.push_back(rule.size());
  }
  return counts;
}

const TriangleRule& triangleRule(int numPoints)
{
  const auto& rules = allTriangleRules();
  const auto found =
      std::find_if(rules.begin(), rules.end(), [numPoints](const TriangleRule& r) { return r.size() == numPoints; });
  if (found == rules.end()) {
    std::ostringstream supported;
    for (const TriangleRule& rule : rules) {
      supported << (&rule == &rules.front() ? "" : ", ") << rule.size();
    }
    throw core::InputError(core::message("triangle quadrature with N_Q = ", numPoints,
                                         " points is not available; use one of ", supported.str(), "."));
  }
  return *found;
}

} // namespace capsula::quadrature
