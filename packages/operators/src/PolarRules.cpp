#include "capsula/operators/PolarRules.hpp"

#include <cmath>
#include <cstddef>

namespace capsula::operators {

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

namespace {

// The polar rules are built in an equilateral triangle with the parametric triangle's
// vertices at E0, E1, E2, then mapped back affinely (xi, eta are the barycentric
// coordinates of vertices 1 and 2). A relabelling of the element's vertices is a symmetry
// of the equilateral triangle, and the Gauss-Legendre rules are symmetric, so the points
// of a rule land on the same physical points whichever local number the target has:
// mirror-image meshes, whose elements list their vertices in the opposite order, then get
// mirror-image integrals (in the right-angled parametric triangle itself, a vertex at the
// right angle and one at 45 degrees would get different rules).
constexpr double halfRootThree = 0.86602540378443864676;
constexpr ParametricPoint equilateral[3] = {{0.0, 0.0}, {1.0, 0.0}, {0.5, halfRootThree}};
// d(xi, eta) = |parametric area| / |equilateral area| d(x, y) = (1/2) / (sqrt(3)/4).
constexpr double areaRatio = 1.0 / halfRootThree;

ParametricPoint toEquilateral(const std::array<double, 2>& parametric)
{
  return {parametric[0] + 0.5 * parametric[1], halfRootThree * parametric[1]};
}

// Maps the rule's points from [first, end) back to the parametric triangle.
void toParametric(ParametricRule& rule, std::size_t first)
{
  for (std::size_t k = first; k < rule.xi.size(); ++k) {
    const double eta = rule.eta[k] / halfRootThree;
    rule.xi[k] -= 0.5 * eta;
    rule.eta[k] = eta;
    rule.weight[k] *= areaRatio;
  }
}

} // namespace

void singularRule(int localNode, const mesh::ShapeParameters& shape, const quadrature::Rule1D& gauss,
                  ParametricRule& rule)
{
  rule.clear();
  if (localNode < 3) {
    // Eq 3.42 at vertex P: the single sub-triangle spanned by the other two vertices.
    appendPolarRule(equilateral[localNode], equilateral[(localNode + 1) % 3], equilateral[(localNode + 2) % 3], gauss,
                    rule);
    toParametric(rule, 0);
    return;
  }
  // Eq 3.43 at the midside node of edge (a, b) = local edge localNode - 3: the
  // sub-triangles (P, b, c) and (P, c, a), c the vertex opposite the edge.
  const int edge = localNode - 3;
  const ParametricPoint& a = equilateral[edge];
  const ParametricPoint& b = equilateral[(edge + 1) % 3];
  const ParametricPoint& opposite = equilateral[(edge + 2) % 3];
  const ParametricPoint apex = toEquilateral(mesh::nodeParametricCoordinates(shape, localNode));
  appendPolarRule(apex, b, opposite, gauss, rule);
  appendPolarRule(apex, opposite, a, gauss, rule);
  toParametric(rule, 0);
}

} // namespace capsula::operators
