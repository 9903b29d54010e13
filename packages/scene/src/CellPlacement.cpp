#include "capsula/scene/CellPlacement.hpp"

#include "capsula/scene/SurfaceGap.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/domain/Domain.hpp>

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

// The node nearest to `wall` (smallest signed distance, the fluid side positive).
int nodeNearestTo(const mesh::SurfaceMesh& cell, const domain::Wall& wall)
{
  int nearest = 0;
  for (int i = 1; i < cell.numNodes(); ++i) {
    if (wall.distance(cell.position(i)[1]) < wall.distance(cell.position(nearest)[1])) {
      nearest = i;
    }
  }
  return nearest;
}

bool isLower(const domain::Wall& wall)
{
  return wall.fluidSide > 0;
}

// The parts of a message that differ between the walls: which node, where the fluid is, which
// way to move the centre, and what else could change.
struct WallWords {
  std::string node, fluid, move, remedy;
};

WallWords wordsFor(const domain::Wall& wall)
{
  if (isLower(wall)) {
    return {"lowest node", "the fluid is y > 0", "Raise", "disable the wall"};
  }
  return {"highest node", core::message("the fluid is y < ", wall.height, " ('Wall/Channel height')"), "Lower",
          "raise 'Wall/Channel height'"};
}

std::string wallName(const domain::Wall& wall)
{
  return isLower(wall) ? "the wall" : "the upper wall";
}

} // namespace

void requireInFluid(const mesh::SurfaceMesh& cell, const std::string& path, const domain::Domain& domain)
{
  for (const domain::Wall& wall : domain.walls()) {
    const int nearest = nodeNearestTo(cell, wall);
    const double y = cell.position(nearest)[1];
    const double gap = wall.distance(y);
    if (gap > 0.0) {
      continue;
    }
    const WallWords words = wordsFor(wall);
    // A cell resting exactly on the wall has its nearest node at gap 0 (or -0): it touches,
    // and "raise it by more than 0" would not say by how much.
    const std::string by = gap < 0.0 ? core::message("by more than ", -gap)
                                     : std::string("so that it clears the wall, e.g. by 0.1 (a thinner gap needs a "
                                                   "finer mesh: 'wall_gap_per_h' in metrics.csv)");
    const std::string fluid =
        isLower(wall) ? std::string("the fluid is y > 0 when 'Wall/Enabled' is true") : words.fluid;
    throw core::InputError(core::message("'", path, "' ", gap < 0.0 ? "crosses " : "touches ", wallName(wall), ": its ",
                                         words.node, " (", nearest, ") lies at y = ", gap < 0.0 ? y : wall.height + 0.0,
                                         " but ", fluid, ". ", words.move, " the y component of '", path,
                                         "/Center' (the height of the centre) ", by, ", or ", words.remedy, "."));
  }
}

void requireWallGaps(const mesh::SurfaceMesh& cell, const std::string& path, const domain::Domain& domain,
                     double minimumGap)
{
  for (const domain::Wall& wall : domain.walls()) {
    const int nearest = nodeNearestTo(cell, wall);
    const double y = cell.position(nearest)[1] + 0.0; // + 0.0: a node at -0 is reported at 0
    const double gap = wall.distance(y) + 0.0;
    const WallWords words = wordsFor(wall);
    core::require<core::InputError>(
        gap > minimumGap, "'", path, "' ", gap > 0.0 ? "starts too close to " : (gap == 0.0 ? "touches " : "crosses "),
        wallName(wall), ": its ", words.node, " (", nearest, ") lies at y = ", y,
        ", not more than 'Wall/Minimum gap' = ", minimumGap,
        isLower(wall) ? " (the fluid is y > 0)" : core::message(" from it (", words.fluid, ")"), ". ", words.move,
        " the y component of '", path, "/Center' (the height of the centre) by more than ", minimumGap - gap,
        ", lower 'Wall/Minimum gap' or ", words.remedy, ".");
  }
}

void requireRoomInDomain(const mesh::SurfaceMesh& cell, const std::string& path, const domain::Domain& domain,
                         double minimumWallGap, double minimumCellGap)
{
  const Box box = boundingBox(cell);
  if (domain.hasUpperWall()) {
    const double height = box.upper[1] - box.lower[1];
    core::require<core::InputError>(
        height + 2.0 * minimumWallGap < domain.channelHeight(), "'Wall/Channel height' = ", domain.channelHeight(),
        " leaves no room for '", path, "', which is ", height, " tall (y from ", box.lower[1], " to ", box.upper[1],
        ") and must keep 'Wall/Minimum gap' = ", minimumWallGap, " from both walls: make the channel taller than ",
        height + 2.0 * minimumWallGap, ", or the cell smaller.");
  }
  static const char* const keys[3] = {"Domain/Periodic length x", "", "Domain/Periodic length z"};
  static const char* const axes[3] = {"x", "y", "z"};
  for (int axis : {domain::flowAxis, domain::vorticityAxis}) {
    if (!domain.isPeriodic(axis)) {
      continue;
    }
    // The cell's nearest image is one period away: its extent plus the cells' minimum gap
    // must fit in one period, or the cell overlaps (or touches) itself.
    const double extent = box.upper[axis] - box.lower[axis];
    const double period = domain.period(axis);
    core::require<core::InputError>(
        extent + minimumCellGap < period, "'", keys[axis], "' = ", period, " is too short for '", path, "', which is ",
        extent, " long along ", axes[axis], " (from ", box.lower[axis], " to ", box.upper[axis],
        "): the cell would overlap its own periodic image, which lies one period away. Make the period longer than ",
        extent + minimumCellGap, " (the cell's length plus 'Cells/Minimum gap' = ", minimumCellGap,
        "), or the cell smaller.");
  }
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

namespace {

// The lattice shifts by which a cell's images lie next to the box: 0 and +-1 period along each
// periodic axis (the images farther away are farther than any cell of the box is long, which
// requireRoomInDomain ensures).
std::vector<Vec3> neighbourShifts(const domain::Domain& domain)
{
  std::vector<Vec3> shifts;
  const int nx = domain.isPeriodic(domain::flowAxis) ? 1 : 0;
  const int nz = domain.isPeriodic(domain::vorticityAxis) ? 1 : 0;
  for (int i = -nx; i <= nx; ++i) {
    for (int k = -nz; k <= nz; ++k) {
      shifts.emplace_back(i * domain.period(domain::flowAxis), 0.0, k * domain.period(domain::vorticityAxis));
    }
  }
  return shifts;
}

mesh::SurfaceMesh translated(const mesh::SurfaceMesh& surface, const Vec3& shift)
{
  mesh::SurfaceMesh copy = surface;
  std::vector<double> positions = surface.positions();
  for (std::size_t i = 0; i < positions.size(); ++i) {
    positions[i] += shift[static_cast<int>(i % 3)];
  }
  copy.setPositions(positions);
  return copy;
}

std::string imageWords(const Vec3& shift)
{
  return shift.isZero() ? std::string()
                        : core::message(" (across the periodic boundary: the second cell's image shifted by (",
                                        shift[0], ", 0, ", shift[2], "))");
}

} // namespace

void requireNoOverlap(const std::vector<const mesh::SurfaceMesh*>& cells, const std::vector<std::string>& paths,
                      double minimumGap, const domain::Domain& domain)
{
  const std::vector<Vec3> shifts = neighbourShifts(domain);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    for (std::size_t j = i + 1; j < cells.size(); ++j) {
      for (const Vec3& shift : shifts) {
        const mesh::SurfaceMesh image = shift.isZero() ? *cells[j] : translated(*cells[j], shift);
        core::require<core::InputError>(!surfacesOverlap(*cells[i], image), "'", paths[i], "' and '", paths[j],
                                        "' overlap at the start: a node of one lies inside the other",
                                        imageWords(shift), ". Move their 'Center's apart (or make the cells smaller).");
        const SurfaceGap gap = minimumSurfaceGap(*cells[i], image);
        core::require<core::InputError>(gap.distance > minimumGap, "'", paths[i], "' and '", paths[j],
                                        "' touch at the start: their surfaces are ", gap.distance, " apart (near (",
                                        gap.onFirst[0], ", ", gap.onFirst[1], ", ", gap.onFirst[2], "))",
                                        imageWords(shift), ", not more than 'Cells/Minimum gap' = ", minimumGap,
                                        ". Move their 'Center's apart (or lower 'Cells/Minimum gap').");
      }
    }
  }
}

} // namespace capsula::scene
