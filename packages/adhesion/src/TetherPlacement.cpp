#include "capsula/adhesion/TetherPlacement.hpp"

#include <capsula/mesh/ElementGeometry.hpp>
#include <capsula/quadrature/TriangleRule.hpp>

#include <array>
#include <cmath>
#include <limits>

namespace capsula::adhesion {

namespace {

// f(xi, eta) = x(xi, eta) . d on one element, with the element's nodal values c_k = x_k . d.
struct ElementHeight {
  mesh::ShapeParameters parameters;
  std::array<double, 6> c{};

  double operator()(double xi, double eta) const
  {
    double phi[6];
    mesh::shapeFunctions(parameters, xi, eta, phi);
    double f = 0.0;
    for (int k = 0; k < 6; ++k) {
      f += phi[k] * c[static_cast<std::size_t>(k)];
    }
    return f;
  }
};

// The points where f may be largest on the triangle: the vertices, the stationary point of
// each edge and the interior stationary point, where they lie inside. f = a0 + a1 xi + a2 eta
// + a3 xi^2 + a4 xi eta + a5 eta^2, its coefficients from its values on the lattice of halves.
std::vector<std::array<double, 2>> candidates(const ElementHeight& f)
{
  const double f00 = f(0.0, 0.0), f10 = f(1.0, 0.0), f01 = f(0.0, 1.0);
  const double fh0 = f(0.5, 0.0), f0h = f(0.0, 0.5), fhh = f(0.5, 0.5);
  const double a3 = 2.0 * f10 - 4.0 * fh0 + 2.0 * f00, a1 = f10 - f00 - a3;
  const double a5 = 2.0 * f01 - 4.0 * f0h + 2.0 * f00, a2 = f01 - f00 - a5;
  const double a4 = 4.0 * (fhh - f00 - 0.5 * (a1 + a2)) - a3 - a5;
  std::vector<std::array<double, 2>> points{{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};
  const auto stationary = [](double linear, double quadratic) {
    return quadratic != 0.0 ? -linear / (2.0 * quadratic) : -1.0;
  };
  if (const double t = stationary(a1, a3); t > 0.0 && t < 1.0) { // eta = 0
    points.push_back({t, 0.0});
  }
  if (const double t = stationary(a2, a5); t > 0.0 && t < 1.0) { // xi = 0
    points.push_back({0.0, t});
  }
  // xi = t, eta = 1 - t: quadratic coefficient a3 - a4 + a5, linear a1 - a2 + a4 - 2 a5.
  if (const double t = stationary(a1 - a2 + a4 - 2.0 * a5, a3 - a4 + a5); t > 0.0 && t < 1.0) {
    points.push_back({t, 1.0 - t});
  }
  const double det = 4.0 * a3 * a5 - a4 * a4;
  if (det != 0.0) {
    const double xi = (-a1 * 2.0 * a5 + a2 * a4) / det, eta = (-a2 * 2.0 * a3 + a1 * a4) / det;
    if (xi > 0.0 && eta > 0.0 && xi + eta < 1.0) {
      points.push_back({xi, eta});
    }
  }
  return points;
}

} // namespace

Receptor farthestMaterialPoint(const mesh::SurfaceMesh& mesh, const double* positions, const ReceptorSet& points,
                               const mesh::Vec3& direction)
{
  Receptor best{0, 0.0, 0.0};
  double largest = -std::numeric_limits<double>::infinity();
  for (int e = 0; e < mesh.numElements(); ++e) {
    ElementHeight f;
    f.parameters = points.shapeParameters(e);
    const mesh::ElementNodes x = mesh.elementNodes(e, positions);
    for (std::size_t k = 0; k < 6; ++k) {
      f.c[k] = x[k].dot(direction);
    }
    for (const auto& p : candidates(f)) {
      const double value = f(p[0], p[1]);
      if (value > largest) {
        largest = value;
        best = {e, p[0], p[1]};
      }
    }
  }
  return best;
}

WeightedPoints materialPatch(const mesh::SurfaceMesh& mesh, const double* positions, const ReceptorSet& points,
                             const Receptor& centre, double radius)
{
  WeightedPoints patch;
  if (radius <= 0.0) {
    patch.points.push_back(centre);
    patch.weights.push_back(1.0);
    return patch;
  }
  const mesh::Vec3 x0 = mesh::surfacePosition(mesh.elementNodes(centre.element, positions),
                                              points.shapeParameters(centre.element), centre.xi, centre.eta);
  const quadrature::TriangleRule& rule = quadrature::triangleRule(7);
  double total = 0.0;
  for (int e = 0; e < mesh.numElements(); ++e) {
    const mesh::ElementNodes x = mesh.elementNodes(e, positions);
    for (int q = 0; q < rule.size(); ++q) {
      const auto k = static_cast<std::size_t>(q);
      const mesh::SurfacePoint s = mesh::evaluateSurfacePoint(x, points.shapeParameters(e), rule.xi[k], rule.eta[k]);
      const double r2 = (s.position - x0).squaredNorm() / (radius * radius);
      if (r2 >= 1.0) {
        continue;
      }
      const double weight = rule.weight[k] * s.metric * (1.0 - r2) * (1.0 - r2);
      patch.points.push_back({e, rule.xi[k], rule.eta[k]});
      patch.weights.push_back(weight);
      total += weight;
    }
  }
  for (double& w : patch.weights) {
    w /= total;
  }
  return patch;
}

} // namespace capsula::adhesion
