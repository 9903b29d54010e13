#pragma once
// The fluid domain of a scene: which plane walls bound it and along which directions it
// is periodic. Every part of the code that needs the geometry of the domain (placement and
// gap checks, contact with a wall, ligand-coated walls, wall stress maps, metrics, the
// choice of the Green's function, the runs' checks that every node stays in the fluid, in
// 3D and for the 2D contour in the x-y plane) asks this object; nothing else assumes a wall
// at y = 0.
//
// Axes: x (0) is the flow direction, y (1) the wall normal, z (2) the vorticity direction.
// Walls are planes y = const: the lower wall y = 0 (the thesis's wall) and, for a channel
// of height H, the upper wall y = H. The domain may be periodic along x and z with periods
// L_x and L_z; positions of cells are never wrapped (a cell that leaves the box keeps its
// true travel), so distances between points use the nearest periodic image.
#include <array>
#include <string>
#include <vector>

namespace capsula::domain {

inline constexpr int flowAxis = 0;
inline constexpr int wallNormalAxis = 1;
inline constexpr int vorticityAxis = 2;

/// A no-slip plane wall y = height; `fluidSide` is +1 when the fluid lies above it (y >
/// height), -1 when below. `name` is what messages call it ("lower wall", "upper wall").
struct Wall {
  double height = 0.0;
  int fluidSide = 1;
  std::string name;

  /// Signed distance of a point at height y from the wall, positive in the fluid.
  double distance(double y) const { return fluidSide * (y - height); }
};

/// The shape of the domain as the deck gives it.
struct DomainShape {
  bool lowerWall = true;      ///< the wall y = 0
  double channelHeight = 0.0; ///< H > 0: a second wall y = H (needs the lower wall); 0: none
  double periodX = 0.0;       ///< L_x > 0: periodic along x; 0: unbounded
  double periodZ = 0.0;       ///< L_z > 0: periodic along z; 0: unbounded
};

class Domain {
public:
  /// Throws core::InputError for a shape that is not a domain (a negative or non-finite
  /// length, a channel without its lower wall).
  explicit Domain(const DomainShape& shape);

  /// Unbounded fluid; fluid above the wall y = 0; a channel 0 < y < H.
  static Domain unbounded();
  static Domain aboveWall();
  static Domain channel(double height);

  const DomainShape& shape() const { return shape_; }
  bool hasLowerWall() const { return shape_.lowerWall; }
  bool hasUpperWall() const { return shape_.channelHeight > 0.0; }
  bool hasWalls() const { return !walls_.empty(); }
  double channelHeight() const { return shape_.channelHeight; }
  /// The walls, lower first.
  const std::vector<Wall>& walls() const { return walls_; }

  /// The period along `axis` (0 for a direction that is not periodic; y never is).
  double period(int axis) const { return periods_[static_cast<std::size_t>(axis)]; }
  bool isPeriodic(int axis) const { return period(axis) > 0.0; }
  bool isPeriodic() const { return isPeriodic(flowAxis) || isPeriodic(vorticityAxis); }

  /// Replaces the separation d = a - b by that of the nearest periodic image of a
  /// (each periodic component brought into [-L/2, L/2]).
  void nearestImage(double d[3]) const;
  /// The separation a - b of the nearest images.
  std::array<double, 3> separation(const double a[3], const double b[3]) const;
  /// The lattice shift (a multiple of the period along each periodic axis, 0 elsewhere)
  /// that brings x into the box [0, L_x) x R x [0, L_z): x + shift is folded.
  std::array<double, 3> foldingShift(const double x[3]) const;

  /// Signed distance of the point x (only its height counts) to the nearest wall, positive
  /// in the fluid; +infinity without walls. `nearest` receives the index in walls() (-1
  /// without walls).
  double distanceToNearestWall(const double x[3], int* nearest = nullptr) const;
  /// Whether x lies strictly inside the fluid (every wall distance > 0; NaN is outside).
  bool inFluid(const double x[3]) const;
  /// The first of `numPoints` points, `dimension` (2 or 3) coordinates each, that is not
  /// strictly inside the fluid (on or through a wall, or at a height that is not a number),
  /// or -1. Only the height counts: coordinate wallNormalAxis in 2D as in 3D.
  int firstPointOutsideFluid(const double* points, int numPoints, int dimension) const;
  /// "the wall" (the lower wall y = 0) or "the upper wall": the wall nearest to a point at
  /// height y, for messages.
  std::string nearestWallName(double y) const;

  /// A phrase for messages and the run's "Terms built" block, e.g. "a channel 0 < y < 10
  /// periodic along x (L_x = 20)".
  std::string describe() const;

private:
  DomainShape shape_;
  std::array<double, 3> periods_{};
  std::vector<Wall> walls_;
};

} // namespace capsula::domain
