#include "capsula/scene/CellPlacement.hpp"

#include "capsula/scene/SurfaceGap.hpp"

#include <capsula/core/Error.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace capsula::scene {

namespace core = capsula::core;
using mesh::Vec3;

namespace {

// Signed solid angle of the flat triangle (a, b, c) seen from the origin (Van Oosterom &
// Strackee 1983): positive when the triangle's normal (b - a) x (c - a) points away.
double solidAngle(const Vec3& a, const Vec3& b, const Vec3& c)
{
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double numerator = a.dot(b.cross(c));
  const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
  return 2.0 * std::atan2(numerator, denominator);
}

struct Box {
  Vec3 lower = Vec3::Constant(HUGE_VAL), upper = Vec3::Constant(-HUGE_VAL);
};

Box boundingBox(const mesh::SurfaceMesh& surface)
{
  Box box;
  for (int i = 0; i < surface.numNodes(); ++i) {
    box.lower = box.lower.cwiseMin(surface.position(i));
    box.upper = box.upper.cwiseMax(surface.position(i));
  }
  return box;
}

bool contains(const Box& box, const Vec3& p)
{
  return (p.array() >= box.lower.array()).all() && (p.array() <= box.upper.array()).all();
}

bool anyNodeInside(const mesh::SurfaceMesh& nodesOf, const mesh::SurfaceMesh& surface)
{
  const Box box = boundingBox(surface);
  for (int i = 0; i < nodesOf.numNodes(); ++i) {
    const Vec3 p = nodesOf.position(i);
    if (contains(box, p) && windingNumber(surface, p) > 0.5) {
      return true;
    }
  }
  return false;
}

} // namespace

namespace {

int lowestNode(const mesh::SurfaceMesh& cell)
{
  int lowest = 0;
  for (int i = 1; i < cell.numNodes(); ++i) {
    if (cell.position(i)[1] < cell.position(lowest)[1]) {
      lowest = i;
    }
  }
  return lowest;
}

} // namespace

void requireAboveWall(const mesh::SurfaceMesh& cell, const std::string& path)
{
  const int lowest = lowestNode(cell);
  const double y = cell.position(lowest)[1];
  if (y > 0.0) {
    return;
  }
  // A cell resting exactly on the wall has its lowest node at y = 0 (or -0): it touches,
  // and "raise it by more than 0" would not say by how much.
  const std::string raise = y < 0.0
                                ? core::message("by more than ", -y)
                                : std::string("so that it clears the wall, e.g. by 0.1 (a thinner gap needs a finer "
                                              "mesh: 'wall_gap_per_h' in metrics.csv)");
  throw core::InputError(
      core::message("'", path, "' ", y < 0.0 ? "crosses" : "touches", " the wall: its lowest node (", lowest,
                    ") lies at y = ", y < 0.0 ? y : 0.0,
                    " but the fluid is y > 0 when 'Wall/Enabled' is true. Raise the y component of '", path,
                    "/Center' (the height of the centre) ", raise, ", or disable the wall."));
}

void requireWallGap(const mesh::SurfaceMesh& cell, const std::string& path, double minimumGap)
{
  const int lowest = lowestNode(cell);
  const double y = cell.position(lowest)[1] + 0.0; // + 0.0: a node at -0 is reported at 0
  core::require<core::InputError>(
      y > minimumGap, "'", path, "' ",
      y > 0.0 ? "starts too close to the wall" : (y == 0.0 ? "touches the wall" : "crosses the wall"),
      ": its lowest node (", lowest, ") lies at y = ", y, ", not more than 'Wall/Minimum gap' = ", minimumGap,
      " (the fluid is y > 0). Raise the y component of '", path, "/Center' (the height of the centre) by more than ",
      minimumGap - y, ", lower 'Wall/Minimum gap' or disable the wall.");
}

double windingNumber(const mesh::SurfaceMesh& surface, const Vec3& point)
{
  // Four flat sub-triangles per element, oriented like the element (outward normal).
  static constexpr std::array<std::array<int, 3>, 4> pieces{{{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}}};
  double total = 0.0;
  for (int e = 0; e < surface.numElements(); ++e) {
    const auto& nodes = surface.element(e);
    for (const auto& piece : pieces) {
      total += solidAngle(surface.position(nodes[piece[0]]) - point, surface.position(nodes[piece[1]]) - point,
                          surface.position(nodes[piece[2]]) - point);
    }
  }
  return total / (4.0 * M_PI);
}

bool surfacesOverlap(const mesh::SurfaceMesh& a, const mesh::SurfaceMesh& b)
{
  const Box boxA = boundingBox(a), boxB = boundingBox(b);
  const bool boxesMeet =
      (boxA.lower.array() <= boxB.upper.array()).all() && (boxB.lower.array() <= boxA.upper.array()).all();
  return boxesMeet && (anyNodeInside(a, b) || anyNodeInside(b, a));
}

void requireNoOverlap(const std::vector<const mesh::SurfaceMesh*>& cells, const std::vector<std::string>& paths,
                      double minimumGap)
{
  for (std::size_t i = 0; i < cells.size(); ++i) {
    for (std::size_t j = i + 1; j < cells.size(); ++j) {
      core::require<core::InputError>(
          !surfacesOverlap(*cells[i], *cells[j]), "'", paths[i], "' and '", paths[j],
          "' overlap at the start: a node of one lies inside the other. Move their 'Center's "
          "apart (or make the cells smaller).");
      const SurfaceGap gap = minimumSurfaceGap(*cells[i], *cells[j]);
      core::require<core::InputError>(gap.distance > minimumGap, "'", paths[i], "' and '", paths[j],
                                      "' touch at the start: their surfaces are ", gap.distance, " apart (near (",
                                      gap.onFirst[0], ", ", gap.onFirst[1], ", ", gap.onFirst[2],
                                      ")), not more than 'Cells/Minimum gap' = ", minimumGap,
                                      ". Move their 'Center's apart (or lower 'Cells/Minimum gap').");
    }
  }
}

} // namespace capsula::scene
