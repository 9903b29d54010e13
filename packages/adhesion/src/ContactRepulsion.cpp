#include "capsula/adhesion/ContactRepulsion.hpp"

#include <capsula/mesh/Measures.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace capsula::adhesion {

namespace {

// The four flat triangles of a 6-node element {v0, v1, v2, m01, m12, m20}, as local nodes.
constexpr int facets[4][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}};

// g(s) = 1 / (e^s - 1) and the shift terms g(1), g'(1) = -e / (e - 1)^2.
double steric(double s)
{
  return 1.0 / std::expm1(s);
}
// g'(s) = -e^s / (e^s - 1)^2.
double stericSlope(double s)
{
  const double m = std::expm1(s);
  return -(m + 1.0) / (m * m);
}
const double stericAtRange = steric(1.0);
const double stericSlopeAtRange = -std::exp(1.0) / ((std::exp(1.0) - 1.0) * (std::exp(1.0) - 1.0));

struct Box {
  mesh::Vec3 lo = mesh::Vec3::Constant(std::numeric_limits<double>::infinity());
  mesh::Vec3 hi = mesh::Vec3::Constant(-std::numeric_limits<double>::infinity());
  void add(const mesh::Vec3& x)
  {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  // Distance from x to the box (0 inside).
  double distance(const mesh::Vec3& x) const
  {
    const mesh::Vec3 outside = (lo - x).cwiseMax(x - hi).cwiseMax(0.0);
    return outside.norm();
  }
};

// The closest point of a segment to x, as the weight t of its second end.
double closestOnSegment(const mesh::Vec3& x, const mesh::Vec3& p, const mesh::Vec3& q)
{
  const mesh::Vec3 e = q - p;
  const double ee = e.squaredNorm();
  return ee > 0.0 ? std::clamp((x - p).dot(e) / ee, 0.0, 1.0) : 0.0;
}

// One pass: the nodes of `from` against the facets of `to`; forces scaled by 1/2.
mesh::Vec3 nodesAgainstFacets(const ContactSettings& contact, const mesh::SurfaceMesh& from, const double* xf,
                              const std::vector<double>& areas, double* forcesFrom, const mesh::SurfaceMesh& to,
                              const double* xt, double* forcesTo)
{
  Box whole;
  std::vector<Box> boxes(static_cast<std::size_t>(to.numElements()));
  for (int e = 0; e < to.numElements(); ++e) {
    for (const int n : to.element(e)) {
      boxes[static_cast<std::size_t>(e)].add(mesh::nodeAt(xt, n));
    }
    whole.add(boxes[static_cast<std::size_t>(e)].lo);
    whole.add(boxes[static_cast<std::size_t>(e)].hi);
  }
  const double range = contact.range;
  mesh::Vec3 total = mesh::Vec3::Zero();
  for (int k = 0; k < from.numNodes(); ++k) {
    const mesh::Vec3 x = mesh::nodeAt(xf, k);
    if (whole.distance(x) >= range) {
      continue;
    }
    double best = range;
    std::array<int, 3> bestNodes{};
    std::array<double, 3> bestWeights{};
    mesh::Vec3 bestPoint = mesh::Vec3::Zero();
    for (int e = 0; e < to.numElements(); ++e) {
      if (boxes[static_cast<std::size_t>(e)].distance(x) >= best) {
        continue;
      }
      const auto& nodes = to.element(e);
      for (const auto& f : facets) {
        const std::array<int, 3> n{nodes[f[0]], nodes[f[1]], nodes[f[2]]};
        const mesh::Vec3 p0 = mesh::nodeAt(xt, n[0]), p1 = mesh::nodeAt(xt, n[1]), p2 = mesh::nodeAt(xt, n[2]);
        const auto w = closestBarycentric(x, p0, p1, p2);
        const mesh::Vec3 c = w[0] * p0 + w[1] * p1 + w[2] * p2;
        const double d = (x - c).norm();
        if (d < best) {
          best = d;
          bestNodes = n;
          bestWeights = w;
          bestPoint = c;
        }
      }
    }
    if (best >= range || best <= 0.0) {
      continue; // out of range, or on the other surface: no direction to push along
    }
    const mesh::Vec3 f =
        (0.5 * repulsionPressure(contact, best) * areas[static_cast<std::size_t>(k)] / best) * (x - bestPoint);
    for (int i = 0; i < 3; ++i) {
      forcesFrom[3 * k + i] += f[i];
      for (int m = 0; m < 3; ++m) {
        forcesTo[3 * bestNodes[static_cast<std::size_t>(m)] + i] -= bestWeights[static_cast<std::size_t>(m)] * f[i];
      }
    }
    total += f;
  }
  return total;
}

} // namespace

double repulsionPressure(const ContactSettings& contact, double gap)
{
  if (gap >= contact.range) {
    return 0.0;
  }
  const double s = std::max(gap, 1e-6 * contact.range) / contact.range;
  return contact.strength * (steric(s) - stericAtRange - (s - 1.0) * stericSlopeAtRange);
}

double repulsionPressureSlope(const ContactSettings& contact, double gap)
{
  if (gap >= contact.range || gap <= 1e-6 * contact.range) {
    return 0.0;
  }
  const double s = gap / contact.range;
  return contact.strength * (stericSlope(s) - stericSlopeAtRange) / contact.range;
}

std::vector<double> nodalAreaShares(const mesh::SurfaceMesh& mesh, const double* positions)
{
  const std::vector<double> elementAreas = mesh::elementAreas(mesh, positions);
  std::vector<double> shares(static_cast<std::size_t>(mesh.numNodes()), 0.0);
  for (int e = 0; e < mesh.numElements(); ++e) {
    for (const int n : mesh.element(e)) {
      shares[static_cast<std::size_t>(n)] += elementAreas[static_cast<std::size_t>(e)] / 6.0;
    }
  }
  return shares;
}

mesh::Vec3 addWallContactForces(const ContactSettings& contact, const mesh::SurfaceMesh& mesh, const double* positions,
                                const std::vector<double>& areas, double* nodalForces)
{
  double total = 0.0;
  for (int k = 0; k < mesh.numNodes(); ++k) {
    const double f = repulsionPressure(contact, positions[3 * k + 1]) * areas[static_cast<std::size_t>(k)];
    nodalForces[3 * k + 1] += f;
    total += f;
  }
  return mesh::Vec3(0.0, total, 0.0);
}

void addWallContactStiffness(const ContactSettings& contact, const mesh::SurfaceMesh& mesh, const double* positions,
                             const std::vector<double>& areas, LoadStiffness& stiffness)
{
  for (int k = 0; k < mesh.numNodes(); ++k) {
    const double slope = repulsionPressureSlope(contact, positions[3 * k + 1]);
    if (slope != 0.0) {
      stiffness.add(3 * k + 1, 3 * k + 1, -slope * areas[static_cast<std::size_t>(k)]);
    }
  }
}

mesh::Vec3 addCellContactForces(const ContactSettings& contact, const mesh::SurfaceMesh& a, const double* xa,
                                const std::vector<double>& areasA, double* forcesA, const mesh::SurfaceMesh& b,
                                const double* xb, const std::vector<double>& areasB, double* forcesB)
{
  const mesh::Vec3 onA = nodesAgainstFacets(contact, a, xa, areasA, forcesA, b, xb, forcesB);
  const mesh::Vec3 onB = nodesAgainstFacets(contact, b, xb, areasB, forcesB, a, xa, forcesA);
  return onA - onB;
}

std::array<double, 3> closestBarycentric(const mesh::Vec3& x, const mesh::Vec3& p0, const mesh::Vec3& p1,
                                         const mesh::Vec3& p2)
{
  // Inside the triangle: the projection onto its plane, when its barycentric weights are >= 0.
  const mesh::Vec3 e1 = p1 - p0, e2 = p2 - p0, r = x - p0;
  const double a11 = e1.dot(e1), a12 = e1.dot(e2), a22 = e2.dot(e2);
  const double det = a11 * a22 - a12 * a12;
  if (det > 1e-14 * a11 * a22) {
    const double b1 = r.dot(e1), b2 = r.dot(e2);
    const double u = (a22 * b1 - a12 * b2) / det, v = (a11 * b2 - a12 * b1) / det;
    if (u >= 0.0 && v >= 0.0 && u + v <= 1.0) {
      return {1.0 - u - v, u, v};
    }
  }
  // Otherwise on an edge (also for a degenerate triangle): the nearest of the three.
  const double t01 = closestOnSegment(x, p0, p1), t12 = closestOnSegment(x, p1, p2), t20 = closestOnSegment(x, p2, p0);
  const std::array<std::array<double, 3>, 3> candidates{
      {{1.0 - t01, t01, 0.0}, {0.0, 1.0 - t12, t12}, {t20, 0.0, 1.0 - t20}}};
  std::array<double, 3> best = candidates[0];
  double bestDistance = std::numeric_limits<double>::infinity();
  for (const auto& w : candidates) {
    const double d = (x - (w[0] * p0 + w[1] * p1 + w[2] * p2)).squaredNorm();
    if (d < bestDistance) {
      bestDistance = d;
      best = w;
    }
  }
  return best;
}

} // namespace capsula::adhesion
