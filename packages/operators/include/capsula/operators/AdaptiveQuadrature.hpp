#pragma once
// Near-singular element integrals by adaptive subdivision in parameter space.
//
// A target close to an element it does not belong to (a node of another cell, a flow
// probe, the image of a node near the wall) makes the integrand peak on a scale smaller
// than the element, and the N_Q-point rule loses accuracy. The parametric triangle is
// split into four (at the edge midpoints), in two passes:
//  1. separation: a (sub-)triangle is split until it is at least `minimumSeparation`
//     of its size away from every pole (the target and its images). Comparing rules on
//     a triangle that holds a narrow peak can agree by accident (both miss the peak);
//     on a separated one the integrand is smooth and the comparison is reliable.
//  2. accuracy: each separated triangle is accepted when the N_Q-point rule on it and
//     the sum of the rule on its four children agree within the tolerance, else each
//     child is treated the same way. The children's sum is kept, so the accepted error
//     is the finer one (about 2^-(p+1) of the estimate for a degree-p rule).
// Each group of the integrand (ElementIntegrals.hpp) is judged on its own against
// tolerance * magnitude, the magnitude being the sum of the largest absolute term of the
// group over the points of the first pass: the size of the element's contribution,
// never zero by cancellation, so the recursion always ends.
#include <capsula/operators/ElementIntegrals.hpp>
#include <capsula/quadrature/TriangleRule.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace capsula::operators {

/// Depth limit of the subdivision: sub-triangles of 2^-16 of the element's size, so a
/// target 1e-4 element sizes away still gets a converged integral.
inline constexpr int maxSubdivisionDepth = 16;

/// Pass 1 splits a triangle closer to a pole than this many times its size.
inline constexpr double minimumSeparation = 0.5;

/// At most this many poles (the target and its images).
inline constexpr int maxPoles = 4;

/// Budget of rule applications per element integral: pass 2 stops refining beyond it.
/// A converging integral needs a few hundred at 1e-4 element sizes; the cap only guards
/// against an integrand that is round-off noise around zero (its magnitude gives no
/// usable scale), which would otherwise refine everywhere to the depth limit.
inline constexpr int maxRuleApplications = 20000;

template <class Integrand>
class AdaptiveElementQuadrature {
public:
  using Value = typename Integrand::Value;
  static constexpr int numGroups = static_cast<int>(Integrand::groups.size()) - 1;

  /// `poles`: the points where the integrand is singular (target and images; at most
  /// maxPoles).
  AdaptiveElementQuadrature(const ElementMap& element, const Integrand& integrand, const quadrature::TriangleRule& rule,
                            double tolerance, const double (*poles)[3], int numPoles)
      : element_(element),
        integrand_(integrand),
        rule_(rule),
        tolerance_(tolerance),
        numPoles_(std::min(numPoles, maxPoles))
  {
    for (int p = 0; p < numPoles_; ++p) {
      for (int i = 0; i < 3; ++i) {
        poles_[p][i] = poles[p][i];
      }
    }
  }

  /// The integral over the whole element.
  Value integrate()
  {
    evaluations_ = 0;
    leaves_.clear();
    std::array<double, numGroups> magnitude{};
    separate({{{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}}}, 0, magnitude);
    for (int g = 0; g < numGroups; ++g) {
      absoluteTolerance_[g] = tolerance_ * magnitude[g];
    }
    Value total{};
    for (const Leaf& leaf : leaves_) {
      add(total, refine(leaf.triangle, leaf.value, leaf.depth));
    }
    return total;
  }

  /// Rule applications the last integrate() used (each N_Q points).
  int ruleApplications() const { return evaluations_; }

private:
  using Triangle = std::array<ParametricPoint, 3>;
  struct Leaf {
    Triangle triangle;
    Value value;
    int depth;
  };

  // Pass 1: split until separated from the poles; keep the rule's value on each leaf.
  void separate(const Triangle& t, int depth, std::array<double, numGroups>& magnitude)
  {
    if (depth + 1 < maxSubdivisionDepth && !separated(t)) {
      for (const Triangle& child : split(t)) {
        separate(child, depth + 1, magnitude);
      }
      return;
    }
    leaves_.push_back({t, integrateOn(t, &magnitude), depth});
    ++evaluations_;
  }

  // Whether every pole is at least minimumSeparation sizes from the triangle's bounding
  // sphere (centre and radius from its corners, edge midpoints and centroid).
  bool separated(const Triangle& t) const
  {
    const ParametricPoint at[7] = {t[0],
                                   t[1],
                                   t[2],
                                   {0.5 * (t[0][0] + t[1][0]), 0.5 * (t[0][1] + t[1][1])},
                                   {0.5 * (t[1][0] + t[2][0]), 0.5 * (t[1][1] + t[2][1])},
                                   {0.5 * (t[2][0] + t[0][0]), 0.5 * (t[2][1] + t[0][1])},
                                   {(t[0][0] + t[1][0] + t[2][0]) / 3.0, (t[0][1] + t[1][1] + t[2][1]) / 3.0}};
    double x[7][3];
    for (int k = 0; k < 7; ++k) {
      element_.position(at[k][0], at[k][1], x[k]);
    }
    const auto distance = [](const double* a, const double* b) {
      return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
    };
    double radius = 0.0;
    for (int k = 0; k < 6; ++k) {
      radius = std::max(radius, distance(x[k], x[6]));
    }
    const double size = std::max({distance(x[0], x[1]), distance(x[1], x[2]), distance(x[2], x[0])});
    for (int p = 0; p < numPoles_; ++p) {
      if (distance(poles_[p], x[6]) - radius < minimumSeparation * size) {
        return false;
      }
    }
    return true;
  }

  static std::array<Triangle, 4> split(const Triangle& t)
  {
    const auto mid = [](const ParametricPoint& a, const ParametricPoint& b) {
      return ParametricPoint{0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])};
    };
    const ParametricPoint m01 = mid(t[0], t[1]), m12 = mid(t[1], t[2]), m20 = mid(t[2], t[0]);
    return {{{t[0], m01, m20}, {m01, t[1], m12}, {m20, m12, t[2]}, {m12, m20, m01}}};
  }

  static Value sum(const std::array<Value, 4>& values)
  {
    Value total{};
    for (const Value& v : values) {
      add(total, v);
    }
    return total;
  }

  static void add(Value& total, const Value& v)
  {
    for (int c = 0; c < Integrand::size; ++c) {
      total[c] += v[c];
    }
  }

  // The N_Q-point rule mapped onto the sub-triangle t (Jacobian = twice its area).
  Value integrateOn(const Triangle& t, std::array<double, numGroups>* magnitude) const
  {
    const double e1[2] = {t[1][0] - t[0][0], t[1][1] - t[0][1]};
    const double e2[2] = {t[2][0] - t[0][0], t[2][1] - t[0][1]};
    const double jacobian = std::abs(e1[0] * e2[1] - e1[1] * e2[0]);
    Value total{}, term;
    for (int k = 0; k < rule_.size(); ++k) {
      const double xi = t[0][0] + rule_.xi[k] * e1[0] + rule_.eta[k] * e2[0];
      const double eta = t[0][1] + rule_.xi[k] * e1[1] + rule_.eta[k] * e2[1];
      integrand_.evaluate(element_.sample(xi, eta, rule_.weight[k] * jacobian), term);
      add(total, term);
      if (magnitude) {
        for (int g = 0; g < numGroups; ++g) {
          double largest = 0.0;
          for (int c = Integrand::groups[g]; c < Integrand::groups[g + 1]; ++c) {
            largest = std::max(largest, std::abs(term[c]));
          }
          (*magnitude)[g] += largest;
        }
      }
    }
    return total;
  }

  bool converged(const Value& coarse, const Value& fine) const
  {
    for (int g = 0; g < numGroups; ++g) {
      for (int c = Integrand::groups[g]; c < Integrand::groups[g + 1]; ++c) {
        if (!(std::abs(fine[c] - coarse[c]) <= absoluteTolerance_[g])) {
          return false;
        }
      }
    }
    return true;
  }

  // Pass 2: accept when the rule on t and on its children agree, else recurse.
  Value refine(const Triangle& t, const Value& coarse, int depth)
  {
    if (evaluations_ + 4 > maxRuleApplications) {
      return coarse;
    }
    std::array<Triangle, 4> children = split(t);
    std::array<Value, 4> childValues;
    for (int k = 0; k < 4; ++k) {
      childValues[k] = integrateOn(children[k], nullptr);
    }
    evaluations_ += 4;
    const Value fine = sum(childValues);
    if (depth + 1 >= maxSubdivisionDepth || converged(coarse, fine)) {
      return fine;
    }
    Value total{};
    for (int k = 0; k < 4; ++k) {
      add(total, refine(children[k], childValues[k], depth + 1));
    }
    return total;
  }

  ElementMap element_; // copies: the quadrature may outlive the arguments
  Integrand integrand_;
  const quadrature::TriangleRule& rule_;
  double tolerance_;
  double poles_[maxPoles][3];
  int numPoles_;
  std::vector<Leaf> leaves_;
  std::array<double, numGroups> absoluteTolerance_{};
  int evaluations_ = 0;
};

/// The integral of `integrand` over the element to `tolerance` (see above), the
/// integrand being singular at integrand.x0 only.
template <class Integrand>
typename Integrand::Value integrateAdaptively(const ElementMap& element, const Integrand& integrand,
                                              const quadrature::TriangleRule& rule, double tolerance)
{
  const double poles[1][3] = {{integrand.x0[0], integrand.x0[1], integrand.x0[2]}};
  return AdaptiveElementQuadrature<Integrand>(element, integrand, rule, tolerance, poles, 1).integrate();
}

} // namespace capsula::operators
