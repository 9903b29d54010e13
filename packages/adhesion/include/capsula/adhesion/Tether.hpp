#pragma once
// A tether: one permanent bond between a cell's membrane and a fixed anchor A on the wall
// y = 0, a linear spring that never breaks (BondSpring.hpp), the 3D counterpart of the
// tethered 2D cell of thesis Chapter 4 (there a membrane point pinned next to the wall).
//
// Placed once, on the cell's shape at t = 0 (TetherSettings, TetherPlacement.hpp): the
// attachment is the material point farthest along the settings' direction (the lowest point
// by default), or a patch of material points x_i around it with weights w_i (sum 1). The
// spring pulls at their weighted mean X = sum_i w_i x_i,
//
//   F = -sigma (L - lambda) (X - A) / L,    L = |X - A|,
//
// and each point takes w_i F, spread onto its element's six nodes by virtual work
// (PointForces.hpp): w_i F = -dE/dx_i of the spring energy E(|X - A|), so the nodal forces sum
// to F and their torque about any point is that of F at X (sum_i w_i x_i = X). Its anchor is
// the given one or the point of the wall below X at t = 0; its rest length the given one or
// L at t = 0. Everything is fixed by the deck and the initial shape: the tether has no state
// of its own, and a restart that rebuilds it from the deck gets it bit for bit.
#include "capsula/adhesion/LoadStiffness.hpp"
#include "capsula/adhesion/Receptors.hpp"
#include "capsula/adhesion/TetherParameters.hpp"

#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/mesh/Vec3.hpp>

#include <string>
#include <vector>

namespace capsula::adhesion {

/// The tether at one state.
struct TetherState {
  mesh::Vec3 attachment = mesh::Vec3::Zero(); ///< X, where the spring pulls
  mesh::Vec3 anchor = mesh::Vec3::Zero();     ///< A, on the wall
  mesh::Vec3 force = mesh::Vec3::Zero();      ///< F on the membrane, G a
  double length = 0.0;                        ///< L = |X - A|, a
  /// The angle of X - A to the wall, degrees: 90 with X straight above A, 0 with X on the wall.
  double inclinationDegrees = 0.0;
};

class Tether {
public:
  /// Places the tether of `settings` on `cell` at node positions `positions` (t = 0, 3 per
  /// node), the material points in the parametrisation of the unstressed shape `reference`.
  /// Throws core::InputError naming `path`'s keys for an attachment point on or below the
  /// wall, an anchor at it, or a patch radius that holds fewer than three quadrature points.
  Tether(const TetherSettings& settings, const mesh::SurfaceMesh& cell, const double* positions,
         const std::vector<double>& reference, const std::string& path = "Tether");

  const TetherSettings& settings() const { return settings_; }
  int cell() const { return settings_.cell; }
  const mesh::Vec3& anchor() const { return anchor_; }
  double restLength() const { return restLength_; }
  /// The material points that share the force, and their weights (sum 1).
  const ReceptorSet& points() const { return points_; }
  const std::vector<double>& weights() const { return weights_; }

  /// X at node positions `positions` of the tethered cell.
  mesh::Vec3 attachment(const mesh::SurfaceMesh& cell, const double* positions) const;
  /// Attachment, force, length and inclination at `positions`.
  TetherState state(const mesh::SurfaceMesh& cell, const double* positions) const;
  /// Adds the tether's nodal forces on the cell to `nodalForces` (3 per node); returns F.
  mesh::Vec3 addNodalForces(const mesh::SurfaceMesh& cell, const double* positions, double* nodalForces) const;
  /// Adds the stiffness -dF_k/dx_l of those nodal forces at `positions` to `stiffness`: with
  /// X = sum_k c_k x_k (c_k the nodes' shares of the weighted shape functions), node k takes
  /// c_k F(X), so the entries are c_k c_l times the spring's stiffness (BondSpring.hpp).
  void addStiffness(const mesh::SurfaceMesh& cell, const double* positions, LoadStiffness& stiffness) const;

  /// The term line of the run log.
  std::string describe() const;

private:
  TetherSettings settings_;
  ReceptorSet points_;
  std::vector<double> weights_;
  mesh::Vec3 anchor_ = mesh::Vec3::Zero();
  double restLength_ = 0.0;
};

/// The angle of the centroid about the anchor, in degrees: atan2(y_c - A_y, x_c - A_x) in the
/// shear plane, 90 with the centroid straight above the anchor, falling as the cell pivots
/// downstream (+x) towards the wall.
double pivotAngleDegrees(const mesh::Vec3& anchor, const mesh::Vec3& centroid);

} // namespace capsula::adhesion
