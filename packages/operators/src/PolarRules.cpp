#include "capsula/operators/PolarRules.hpp"

#include <cmath>

namespace capsula::operators {

namespace {

constexpr ParametricPoint vertex[3] = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};

} // namespace

void appendPolarRule(const ParametricPoint& apex, const ParametricPoint& a, const ParametricPoint& b,
                     const quadrature::Rule1D& gauss, ParametricRule& rule)
{
  // Foot F of the perpendicular from the apex onto side ab, its length p, and the
  // signed positions sigma of a and b along the side, measured from F.
  const double sideX = b[0] - a[0];
  const double sideY = b[1] - a[1];
  const double length = std::hypot(sideX, sideY);
  const double ex = sideX / length;
  const double ey = sideY / length;
  const double sigmaA = (a[0] - apex[0]) * ex + (a[1] - apex[1]) * ey;
  const double footX = a[0] - sigmaA * ex;
  const double footY = a[1] - sigmaA * ey;
  const double p = std::hypot(footX - apex[0], footY - apex[1]);
  const double uA = std::asinh(sigmaA / p);
  const double uB = std::asinh((sigmaA + length) / p);
  const int n = static_cast<int>(gauss.points.size());
  for (int i = 0; i < n; ++i) {
    // The ray towards Q = F + p sinh(u) e: reach R = |Q - apex| = p cosh u, dtheta = du / cosh u.
    const double u = uA + gauss.points[i] * (uB - uA);
    const double sigma = p * std::sinh(u);
    const double toX = footX + sigma * ex - apex[0];
    const double toY = footY + sigma * ey - apex[1];
    // r' dr' dtheta = (s R)(R ds)(du / cosh u) = p^2 cosh(u) s ds du.
    const double angularWeight = gauss.weights[i] * (uB - uA) * p * p * std::cosh(u);
    for (int k = 0; k < n; ++k) {
      const double s = gauss.points[k];
      rule.xi.push_back(apex[0] + s * toX);
      rule.eta.push_back(apex[1] + s * toY);
      rule.weight.push_back(angularWeight * gauss.weights[k] * s);
    }
  }
}

void singularRule(int localNode, const mesh::ShapeParameters& shape, const quadrature::Rule1D& gauss,
                  ParametricRule& rule)
{
  rule.clear();
  if (localNode < 3) {
    // Eq 3.42 at vertex P: the single sub-triangle spanned by the other two vertices.
    appendPolarRule(vertex[localNode], vertex[(localNode + 1) % 3], vertex[(localNode + 2) % 3], gauss,
                    rule);
    return;
  }
  // Eq 3.43 at the midside node of edge (a, b) = local edge localNode - 3: the
  // sub-triangles (P, b, c) and (P, c, a), c the vertex opposite the edge.
  const auto c = mesh::nodeParametricCoordinates(shape, localNode);
  const int edge = localNode - 3;
  const ParametricPoint& a = vertex[edge];
  const ParametricPoint& b = vertex[(edge + 1) % 3];
  const ParametricPoint& opposite = vertex[(edge + 2) % 3];
  const ParametricPoint apex = {c[0], c[1]};
  appendPolarRule(apex, b, opposite, gauss, rule);
  appendPolarRule(apex, opposite, a, gauss, rule);
}

} // namespace capsula::operators
