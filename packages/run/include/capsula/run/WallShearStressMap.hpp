#pragma once
// The principal shear stress on a patch of a wall around the cells (thesis eqs
// 3.59-3.63, Figs 5.17-5.22), and the wall areas upstream and downstream of a cell where
// it exceeds the ambient level by a given fraction (5% in the thesis).
//
// Any wall of the domain (domain::Wall: the lower wall y = 0 or a channel's upper wall
// y = H) carries its own map. The derivatives are taken along the wall's normal n into the
// fluid (+e_y on the lower wall, -e_y on the upper): du/dn and dw/dn are the tangential
// traction of the fluid on that wall, in units of mu k. Plane Couette flow u = k y reads
// du/dn = +k on the lower wall and -k on the upper (the fluid holds the sliding wall back);
// Poiseuille flow u = k y (1 - y / H) reads +k on both (domain::FlowProfile::wallShearRate).
// The principal stress sqrt((du/dn)^2 + (dw/dn)^2) is the undisturbed |k| on either wall.
//
// Dimensionless units of the scene: stress in mu k, so the undisturbed shear flow
// u_inf = (y, 0, 0) puts the ambient stress sigma_SS = 1 on the whole wall.
#include <capsula/domain/Domain.hpp>
#include <capsula/mesh/Vec3.hpp>
#include <capsula/operators/BoundaryIntegralSolver.hpp>
#include <capsula/operators/WallShearStress.hpp>

#include <vector>

namespace capsula::run {

/// A uniform grid on the wall y = wall.height: nodes (x_i, wall.height, z_j),
/// x_i = xMin + i h, z_j = zMin + j h.
struct WallGrid {
  domain::Wall wall{0.0, 1, "lower wall"}; ///< the wall the grid lies on
  double xMin = 0.0, zMin = 0.0, spacing = 1.0;
  int nx = 0, nz = 0;

  int numNodes() const { return nx * nz; }
  int index(int i, int j) const { return j * nx + i; }
  mesh::Vec3 node(int i, int j) const { return {xMin + i * spacing, wall.height, zMin + j * spacing}; }
  std::vector<mesh::Vec3> nodes() const;

  /// The grid on `wall` covering [cx - upstream, cx + downstream] x [cz - halfWidth,
  /// cz + halfWidth] around the point (cx, cz) with the given spacing (the extents are
  /// rounded up to whole spacings, so the centre stays on a node).
  static WallGrid around(const domain::Wall& wall, double cx, double cz, double upstream, double downstream,
                         double halfWidth, double spacing);
};

struct ElevatedStressAreas {
  double upstream = 0.0;   ///< wall area with x < xCell and stress >= threshold
  double downstream = 0.0; ///< wall area with x > xCell and stress >= threshold
  double minimum = 0.0;    ///< smallest stress on the grid
  double maximum = 0.0;    ///< largest stress on the grid
};

/// du/dn, dw/dn and sigma_SS = sqrt((du/dn)^2 + (dw/dn)^2) (eqs 3.60-3.63) at the nodes of
/// `grid`, on the wall grid.wall, n its normal into the fluid (see above), from the fluid
/// velocity (eq 3.59) at the distances h, 2h, 3h, 4h from the wall along n and the wall's
/// own velocity u_w (no slip: the undisturbed flow there, 0 on the lower wall, k H on
/// Couette's upper wall):
///   du/dn(0) = (-25 u_w + 48 u(h) - 36 u(2h) + 16 u(3h) - 3 u(4h)) / (12 h) + O(h^4),
/// the stencil of operators::wallShearStress without a flow point ON the wall, where the
/// wall kernel vanishes identically and the adaptive near-singular quadrature (relative
/// to a zero integral) would subdivide to its depth limit. The result's dudy and dwdy hold
/// du/dn and dw/dn (on the lower wall n = e_y, so they are du/dy and dw/dy). Collective.
operators::WallShearStress wallShearStressOnGrid(operators::BoundaryIntegralSolver& solver, const WallGrid& grid,
                                                 double step, const operators::LoadDensity& load,
                                                 const double* nodeVelocities, const operators::FlowConditions& flow);

/// Wall areas where the stress leaves the range of an isolated cell's map (thesis Figs 6.6,
/// 6.12: where a pair of cells puts less stress on the wall than one cell ever does, or more).
struct OutsideRangeAreas {
  double below = 0.0; ///< wall area with stress < lowest
  double above = 0.0; ///< wall area with stress > highest
};

/// Areas where `stress` (one value per grid node) is below `lowest` or above `highest`,
/// with the node areas of elevatedStressAreas.
OutsideRangeAreas areasOutsideRange(const WallGrid& grid, const std::vector<double>& stress, double lowest,
                                    double highest);

/// Areas where `stress` (one value per grid node) is >= threshold. Each node carries the
/// area of its dual cell (h^2, halved on an edge, quartered at a corner: the trapezoidal
/// rule), and nodes at x == xCell are shared half and half.
ElevatedStressAreas elevatedStressAreas(const WallGrid& grid, const std::vector<double>& stress, double xCell,
                                        double threshold);

} // namespace capsula::run
