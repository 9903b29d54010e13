#include "capsula/adhesion/ContactRepulsion.hpp"

#include <capsula/mesh/ElementGeometry.hpp>
#include <capsula/mesh/Measures.hpp>
#include <capsula/quadrature/TriangleRule.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

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

// The 7-point rule on each of the m^2 congruent triangles that split the parametric
// triangle (corners at multiples of 1/m): degree 5 on every piece, so the steep pressure near
// the range is sampled m times more finely in each direction than by the rule itself.
quadrature::TriangleRule subdividedRule(int m)
{
  const quadrature::TriangleRule& base = quadrature::triangleRule(7);
  quadrature::TriangleRule rule;
  rule.degree = base.degree;
  const double h = 1.0 / m;
  const auto addPiece = [&](double x0, double y0, double dx1, double dy1, double dx2, double dy2) {
    for (int q = 0; q < base.size(); ++q) {
      rule.xi.push_back(x0 + base.xi[q] * dx1 + base.eta[q] * dx2);
      rule.eta.push_back(y0 + base.xi[q] * dy1 + base.eta[q] * dy2);
      rule.weight.push_back(base.weight[q] * h * h);
    }
  };
  for (int i = 0; i < m; ++i) {
    for (int j = 0; i + j < m; ++j) {
      addPiece(i * h, j * h, h, 0.0, 0.0, h); // the piece with its right angle at (i, j) / m
      if (i + j < m - 1) {
        addPiece((i + 1) * h, (j + 1) * h, -h, 0.0, 0.0, -h); // the piece turned by 180 degrees
      }
    }
  }
  return rule;
}

// Subdivisions for the wall (the gap is y, a point costs O(1)) and for a pair of cells (a
// point costs a search of the other cell's facets).
const quadrature::TriangleRule& wallRule()
{
  static const quadrature::TriangleRule rule = subdividedRule(8);
  return rule;
}
const quadrature::TriangleRule& cellRule()
{
  static const quadrature::TriangleRule rule = subdividedRule(2);
  return rule;
}

// Whether any point of element e can lie within `reach` of the plane y = 0: its lowest node
// less a quarter of its largest vertex-to-vertex chord c. A surface of curvature 1 / R bulges
// by c^2 / (8 R) between nodes c apart, less than c / 4 wherever c < 2 R.
bool mayReachWall(const mesh::ElementNodes& x, const ContactWall& wall, double reach)
{
  double lowest = wall.gap(x[0][1]);
  double chord = 0.0;
  for (int i = 0; i < 6; ++i) {
    lowest = std::min(lowest, wall.gap(x[static_cast<std::size_t>(i)][1]));
  }
  for (int i = 0; i < 3; ++i) {
    chord = std::max(chord, (x[static_cast<std::size_t>(i)] - x[static_cast<std::size_t>((i + 1) % 3)]).norm());
  }
  return lowest - 0.25 * chord < reach;
}

// Calls visit(e, phi, g, dS) at every point of the wall rule on the elements that can reach
// the range: phi the six shape functions there, g its gap to the wall, dS its weight times h_s.
template <class Visit>
void forEachWallPoint(const ContactSettings& contact, const ContactWall& wall, const mesh::SurfaceMesh& mesh,
                      const double* positions, Visit&& visit)
{
  const quadrature::TriangleRule& rule = wallRule();
  for (int e = 0; e < mesh.numElements(); ++e) {
    const mesh::ElementNodes x = mesh.elementNodes(e, positions);
    if (!mayReachWall(x, wall, contact.range)) {
      continue;
    }
    const mesh::ShapeParameters p = mesh::shapeParameters(x);
    for (int q = 0; q < rule.size(); ++q) {
      const mesh::SurfacePoint s = mesh::evaluateSurfacePoint(x, p, rule.xi[q], rule.eta[q]);
      const double gap = wall.gap(s.position[1]);
      if (gap >= contact.range) {
        continue;
      }
      double phi[6];
      mesh::shapeFunctions(p, rule.xi[q], rule.eta[q], phi);
      visit(e, phi, gap, rule.weight[q] * s.metric);
    }
  }
}

// The closest point of the flat-faceted surface `to` to x within `best` (four flat triangles
// per element): its facet's nodes and barycentric weights; returns the distance (`best` if
// none is closer).
struct FacetPoint {
  double distance;
  std::array<int, 3> nodes{};
  std::array<double, 3> weights{};
  mesh::Vec3 point = mesh::Vec3::Zero();
};
FacetPoint closestFacetPoint(const mesh::Vec3& x, const mesh::SurfaceMesh& to, const double* xt,
                             const std::vector<Box>& boxes, double best)
{
  FacetPoint found{best};
  for (int e = 0; e < to.numElements(); ++e) {
    if (boxes[static_cast<std::size_t>(e)].distance(x) >= found.distance) {
      continue;
    }
    const auto& nodes = to.element(e);
    for (const auto& f : facets) {
      const std::array<int, 3> n{nodes[f[0]], nodes[f[1]], nodes[f[2]]};
      const mesh::Vec3 p0 = mesh::nodeAt(xt, n[0]), p1 = mesh::nodeAt(xt, n[1]), p2 = mesh::nodeAt(xt, n[2]);
      const auto w = closestBarycentric(x, p0, p1, p2);
      const mesh::Vec3 c = w[0] * p0 + w[1] * p1 + w[2] * p2;
      const double d = (x - c).norm();
      if (d < found.distance) {
        found = FacetPoint{d, n, w, c};
      }
    }
  }
  return found;
}

// The bounding boxes of the elements of `to`, and of all of them.
Box elementBoxes(const mesh::SurfaceMesh& to, const double* xt, std::vector<Box>& boxes)
{
  Box whole;
  boxes.assign(static_cast<std::size_t>(to.numElements()), Box{});
  for (int e = 0; e < to.numElements(); ++e) {
    for (const int n : to.element(e)) {
      boxes[static_cast<std::size_t>(e)].add(mesh::nodeAt(xt, n));
    }
    whole.add(boxes[static_cast<std::size_t>(e)].lo);
    whole.add(boxes[static_cast<std::size_t>(e)].hi);
  }
  return whole;
}

// Adds f at the facet point c with its barycentric weights on the facet's nodes.
void addAtFacetPoint(const FacetPoint& c, const mesh::Vec3& f, double* forces)
{
  for (int m = 0; m < 3; ++m) {
    for (int i = 0; i < 3; ++i) {
      forces[3 * c.nodes[static_cast<std::size_t>(m)] + i] += c.weights[static_cast<std::size_t>(m)] * f[i];
    }
  }
}

// One pass of the 'Nodal area' load: the nodes of `from` against the facets of `to`, each
// with a sixth of its elements' areas; forces scaled by 1/2.
mesh::Vec3 nodesAgainstFacets(const ContactSettings& contact, const mesh::SurfaceMesh& from, const double* xf,
                              double* forcesFrom, const mesh::SurfaceMesh& to, const double* xt, double* forcesTo)
{
  std::vector<Box> boxes;
  const Box whole = elementBoxes(to, xt, boxes);
  const std::vector<double> areas = nodalAreaShares(from, xf);
  mesh::Vec3 total = mesh::Vec3::Zero();
  for (int k = 0; k < from.numNodes(); ++k) {
    const mesh::Vec3 x = mesh::nodeAt(xf, k);
    if (whole.distance(x) >= contact.range) {
      continue;
    }
    const FacetPoint c = closestFacetPoint(x, to, xt, boxes, contact.range);
    if (c.distance >= contact.range || c.distance <= 0.0) {
      continue;
    }
    const mesh::Vec3 f =
        (0.5 * repulsionPressure(contact, c.distance) * areas[static_cast<std::size_t>(k)] / c.distance) *
        (x - c.point);
    for (int i = 0; i < 3; ++i) {
      forcesFrom[3 * k + i] += f[i];
    }
    addAtFacetPoint(c, -f, forcesTo);
    total += f;
  }
  return total;
}

// One pass: the pressure at the quadrature points of `from` against the facets of `to`,
// scaled by 1/2.
mesh::Vec3 pointsAgainstFacets(const ContactSettings& contact, const mesh::SurfaceMesh& from, const double* xf,
                               double* forcesFrom, const mesh::SurfaceMesh& to, const double* xt, double* forcesTo)
{
  std::vector<Box> boxes;
  const Box whole = elementBoxes(to, xt, boxes);
  const double range = contact.range;
  const quadrature::TriangleRule& rule = cellRule();
  mesh::Vec3 total = mesh::Vec3::Zero();
  for (int e = 0; e < from.numElements(); ++e) {
    const mesh::ElementNodes x = from.elementNodes(e, xf);
    Box box;
    for (const mesh::Vec3& node : x) {
      box.add(node);
    }
    const double chord = (box.hi - box.lo).norm();
    if (whole.distance(0.5 * (box.lo + box.hi)) >= range + 0.5 * chord) {
      continue; // no point of this element comes within the range of `to`'s bounding box
    }
    const mesh::ShapeParameters p = mesh::shapeParameters(x);
    const auto& nodes = from.element(e);
    for (int q = 0; q < rule.size(); ++q) {
      const mesh::SurfacePoint s = mesh::evaluateSurfacePoint(x, p, rule.xi[q], rule.eta[q]);
      if (whole.distance(s.position) >= range) {
        continue;
      }
      const FacetPoint c = closestFacetPoint(s.position, to, xt, boxes, range);
      if (c.distance >= range || c.distance <= 0.0) {
        continue; // out of range, or on the other surface: no direction to push along
      }
      const mesh::Vec3 f = (0.5 * repulsionPressure(contact, c.distance) * rule.weight[q] * s.metric / c.distance) *
                           (s.position - c.point);
      double phi[6];
      mesh::shapeFunctions(p, rule.xi[q], rule.eta[q], phi);
      for (int k = 0; k < 6; ++k) {
        for (int i = 0; i < 3; ++i) {
          forcesFrom[3 * nodes[static_cast<std::size_t>(k)] + i] += phi[k] * f[i];
        }
      }
      addAtFacetPoint(c, -f, forcesTo);
      total += f;
    }
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
                                double* nodalForces, const ContactWall& wall)
{
  double total = 0.0;
  const double side = wall.fluidSide;
  if (contact.load == ContactLoad::NodalArea) {
    const std::vector<double> areas = nodalAreaShares(mesh, positions);
    for (int k = 0; k < mesh.numNodes(); ++k) {
      const double f =
          side * repulsionPressure(contact, wall.gap(positions[3 * k + 1])) * areas[static_cast<std::size_t>(k)];
      nodalForces[3 * k + 1] += f;
      total += f;
    }
    return mesh::Vec3(0.0, total, 0.0);
  }
  forEachWallPoint(contact, wall, mesh, positions, [&](int e, const double phi[6], double gap, double dS) {
    const double f = side * repulsionPressure(contact, gap) * dS;
    const auto& nodes = mesh.element(e);
    for (int k = 0; k < 6; ++k) {
      nodalForces[3 * nodes[static_cast<std::size_t>(k)] + 1] += phi[k] * f;
    }
    total += f;
  });
  return mesh::Vec3(0.0, total, 0.0);
}

void addWallContactStiffness(const ContactSettings& contact, const mesh::SurfaceMesh& mesh, const double* positions,
                             LoadStiffness& stiffness, const ContactWall& wall)
{
  // F_y = s p(g) with g = s (y - h): dF_y/dy = s^2 p'(g) = p'(g) on either side of a wall.
  if (contact.load == ContactLoad::NodalArea) { // diagonal, at frozen area shares
    const std::vector<double> areas = nodalAreaShares(mesh, positions);
    for (int k = 0; k < mesh.numNodes(); ++k) {
      const double slope = repulsionPressureSlope(contact, wall.gap(positions[3 * k + 1]));
      if (slope != 0.0) {
        stiffness.add(3 * k + 1, 3 * k + 1, -slope * areas[static_cast<std::size_t>(k)]);
      }
    }
    return;
  }
  // Element matrices, in the order the elements are visited.
  std::vector<std::pair<int, std::array<double, 36>>> blocks;
  forEachWallPoint(contact, wall, mesh, positions, [&](int e, const double phi[6], double gap, double dS) {
    const double slope = repulsionPressureSlope(contact, gap);
    if (slope == 0.0) {
      return;
    }
    if (blocks.empty() || blocks.back().first != e) {
      blocks.emplace_back(e, std::array<double, 36>{});
    }
    std::array<double, 36>& K = blocks.back().second;
    for (int k = 0; k < 6; ++k) {
      for (int l = 0; l < 6; ++l) {
        K[static_cast<std::size_t>(6 * k + l)] -= slope * dS * phi[k] * phi[l];
      }
    }
  });
  for (const auto& [e, K] : blocks) {
    const auto& nodes = mesh.element(e);
    for (int k = 0; k < 6; ++k) {
      for (int l = 0; l < 6; ++l) {
        stiffness.add(3 * nodes[static_cast<std::size_t>(k)] + 1, 3 * nodes[static_cast<std::size_t>(l)] + 1,
                      K[static_cast<std::size_t>(6 * k + l)]);
      }
    }
  }
}

mesh::Vec3 addCellContactForces(const ContactSettings& contact, const mesh::SurfaceMesh& a, const double* xa,
                                double* forcesA, const mesh::SurfaceMesh& b, const double* xb, double* forcesB)
{
  const auto pass = contact.load == ContactLoad::NodalArea ? nodesAgainstFacets : pointsAgainstFacets;
  const mesh::Vec3 onA = pass(contact, a, xa, forcesA, b, xb, forcesB);
  const mesh::Vec3 onB = pass(contact, b, xb, forcesB, a, xa, forcesA);
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
