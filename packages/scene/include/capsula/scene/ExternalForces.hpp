#pragma once
// The forces from outside on a scene's membranes, only those the deck enables, as nodal
// forces on each cell (3 per node) that its membrane passes on to the fluids with its own
// load (Delta f = -div_s T - f_ext):
//   - the receptor-ligand bonds to the wall ('Adhesion', SceneBonds.hpp), frozen over a
//     step's stages;
//   - the tether of one cell to its anchor on the wall ('Tether', adhesion/Tether.hpp);
//   - the short-range contact repulsion of the wall and between the cells ('Contact',
//     adhesion/ContactRepulsion.hpp).
// Each is spread onto the nodes so that the nodal forces sum to the term's force and carry
// its torque (virtual work).
#include "capsula/scene/SceneBonds.hpp"
#include "capsula/scene/SceneDescription.hpp"

#include <capsula/adhesion/ContactRepulsion.hpp>
#include <capsula/adhesion/Tether.hpp>
#include <capsula/mesh/SurfaceMesh.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace capsula::scene {

/// The walls of `domain` as the contact repulsion takes them (lower first).
std::vector<adhesion::ContactWall> contactWalls(const domain::Domain& domain);

class ExternalForces {
public:
  /// The terms `description` enables for `cells` (at their positions of t = 0, where the
  /// tether is placed), with the membranes' unstressed shapes `references` (3 per node), on
  /// which the receptors and the tether's material points are placed.
  ExternalForces(const SceneDescription& description, const std::vector<mesh::SurfaceMesh>& cells,
                 const std::vector<std::vector<double>>& references);

  /// True if some term is enabled (otherwise forces() is null and nothing is computed).
  bool any() const { return !forces_.empty(); }
  /// One line per term built (the run log, summary.json).
  const std::vector<std::string>& terms() const { return terms_; }

  /// The nodal forces of every term on every cell, the cells where they stand now.
  void compute(const std::vector<mesh::SurfaceMesh>& cells);
  /// Cell c's nodal forces of the last compute(), or null without any term.
  const std::vector<double>* forces(int c) const
  {
    return forces_.empty() ? nullptr : &forces_[static_cast<std::size_t>(c)];
  }

  bool hasBonds() const { return bonds_.has_value(); }
  const SceneBonds& bonds() const { return *bonds_; }
  SceneBonds& bonds() { return *bonds_; }
  bool hasTether() const { return tether_.has_value(); }
  const adhesion::Tether& tether() const { return *tether_; }

private:
  /// The mean of the cell's node positions.
  static std::array<double, 3> nodeCentre(const mesh::SurfaceMesh& cell);
  /// The lattice vector that moves a cell centred at b next to one centred at a.
  std::array<double, 3> imageShift(const std::array<double, 3>& a, const std::array<double, 3>& b) const;

  domain::Domain domain_;                    // its walls repel; its periodic images touch
  std::vector<adhesion::ContactWall> walls_; // the domain's walls, as contact takes them
  adhesion::ContactSettings contact_;
  std::vector<std::vector<double>> forces_; // per cell, 3 per node; empty without any term
  std::optional<SceneBonds> bonds_;         // with 'Adhesion/Enabled'
  std::optional<adhesion::Tether> tether_;  // with 'Tether/Enabled'
  std::vector<std::string> terms_;
};

} // namespace capsula::scene
