#include <capsula/quadrature/TriangleRule.hpp>

#include <capsula/core/Error.hpp>
#include <capsula/quadrature/GaussLegendre.hpp>

namespace capsula::quadrature {

TriangleRule collapsedTriangleRule(int nPerDirection)
{
  core::require<core::InputError>(nPerDirection >= 1, "collapsed triangle rule order ", nPerDirection,
                                  " is invalid; use at least 1 point per direction.");
  const Rule1D gauss = gaussLegendre(nPerDirection, 0.0, 1.0);
  TriangleRule rule;
  // A polynomial of degree d in (xi, eta) becomes degree d + 1 in u (with the Jacobian
  // 1 - u) and d in v, so the n-point Gauss product is exact up to d = 2n - 2.
  rule.degree = 2 * nPerDirection - 2;
  for (std::size_t i = 0; i < gauss.points.size(); ++i) {
    const double u = gauss.points[i];
    for (std::size_t j = 0; j < gauss.points.size(); ++j) {
      const double v = gauss.points[j];
      rule.xi.push_back(u);
      rule.eta.push_back((1.0 - u) * v);
      rule.weight.push_back(gauss.weights[i] * gauss.weights[j] * (1.0 - u));
    }
  }
  return rule;
}

} // namespace capsula::quadrature
