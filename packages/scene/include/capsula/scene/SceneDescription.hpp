#pragma once
// The physical model a validated deck asks for, in plain values (SceneParameters.hpp lists
// the keys). Reading it checks what the validators cannot see alone: cells numbered 0..N-1
// without gaps, a fixed height that needs the wall, contact, adhesion and tether forces that
// need the virtual-work load, bonds and a tether that need the wall and meshes whose material
// points stay put, a tether on a cell the scene has.
#include <capsula/adhesion/AdhesionParameters.hpp>
#include <capsula/adhesion/ContactParameters.hpp>
#include <capsula/adhesion/TetherParameters.hpp>
#include <capsula/domain/Domain.hpp>
#include <capsula/domain/FlowProfile.hpp>
#include <capsula/elasticity/MembraneLawRegistry.hpp>
#include <capsula/mesh/AdaptionParameters.hpp>
#include <capsula/mesh/RedistributionParameters.hpp>
#include <capsula/operators/ShearRate.hpp>

#include <Teuchos_ParameterList.hpp>

#include <memory>
#include <string>
#include <vector>

namespace capsula::scene {

struct CellDescription {
  std::string path;                             ///< "Cells/Cell 0", for messages
  std::string type;                             ///< 'Type': the suspension's cell type, or empty
  Teuchos::ParameterList surface;               ///< the cell's sublist (mesh::buildCellSurface reads it)
  std::string membraneLaw;                      ///< 'Membrane law': a registered name ("NeoHookean", "Skalak")
  Teuchos::ParameterList membraneLawParameters; ///< the law's own keys (Skalak: 'Area dilation C')
  /// The law, built by the registry from the name, 'Shear modulus' and the law's keys.
  std::shared_ptr<const elasticity::MembraneLaw> law;
  std::string membraneForces;        ///< "Virtual work" or "Contour integral"
  double shearModulus = 1.0;         ///< relative to the G of the capillary number
  double prestress = 0.0;            ///< alpha (eq 3.45)
  double viscosityRatio = 1.0;       ///< lambda: the cell's 'Viscosity ratio', else 'Flow/Viscosity ratio'
  double bendingModulus = 0.0;       ///< E_b = k_b / (G a^2); 0: no bending term
  double spontaneousCurvature = 0.0; ///< c0 a
  std::string bendingReference;      ///< "Flat" or "Initial shape"
  bool fixedHeight = false;
  bool conserveVolume = false; ///< 'Conserve volume': VolumeConstraint
  int meshLevel = 0;
};

struct SceneDescription {
  double capillaryNumber = 1.0;
  double viscosityRatio = 1.0;    ///< 'Flow/Viscosity ratio': the lambda of cells without their own
  operators::ShearRate shearRate; ///< 'Flow/Shear rate': k(t) over its mean
  domain::Domain domain = domain::Domain::aboveWall(); ///< 'Wall', 'Domain': walls and periodic box
  /// 'Flow/Profile' in `domain`: simple shear, plane Couette or plane Poiseuille flow
  domain::FlowProfile flowProfile{domain::FlowProfileKind::Shear, domain::Domain::aboveWall()};
  bool wall = true; ///< domain.hasLowerWall(): the lower wall y = 0
  std::vector<CellDescription> cells;
  double minimumGap = 0.05;                        ///< 'Cells/Minimum gap': closer surfaces stop the run
  double minimumWallGap = 0.025;                   ///< 'Wall/Minimum gap': a new run must start farther up
  mesh::RedistributionSettings meshRegularisation; ///< 'Mesh regularisation'
  mesh::AdaptionSettings meshAdaption;             ///< 'Mesh adaption'
  adhesion::ContactSettings contact;               ///< 'Contact': the short-range repulsion
  adhesion::AdhesionSettings adhesion;             ///< 'Adhesion': receptor-ligand bonds to the wall
  adhesion::TetherSettings tether;                 ///< 'Tether': one permanent bond to an anchor on the wall

  int numCells() const { return static_cast<int>(cells.size()); }
  /// Each cell's lambda, in cell order.
  std::vector<double> viscosityRatios() const;
  /// Whether every cell has lambda = 1 (no double layer, no linear solve).
  bool allViscosityRatiosOne() const;
  bool anyFixedHeight() const;
};

/// Reads a validated scene deck, building each cell's membrane law from `laws`. Throws
/// core::InputError naming the key for the inconsistencies listed above and for a law
/// `laws` does not hold.
SceneDescription describeScene(const Teuchos::ParameterList& deck,
                               const elasticity::MembraneLawRegistry& laws = elasticity::builtInMembraneLaws());

} // namespace capsula::scene
