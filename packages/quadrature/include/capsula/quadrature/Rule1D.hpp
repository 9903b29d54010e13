#pragma once
// A one-dimensional quadrature rule: int f(x) w(x) dx ~= sum_k weights[k] f(points[k]),
// where w is the rule's weight function (1 for Gauss-Legendre, -ln x for the log rule).
#include <vector>

namespace capsula::quadrature {

struct Rule1D {
  std::vector<double> points;  ///< ascending
  std::vector<double> weights; ///< weights[k] belongs to points[k]
};

} // namespace capsula::quadrature
