#pragma once
// The deck's "Adhesion" sublist: receptor-ligand bonds between a cell's membrane and a
// ligand-coated wall (the lower wall y = 0, or a channel's upper wall y = H), after Hammer's Adhesive Dynamics (Hammer & Apte, Biophys J 63:35,
// 1992; Chang, Tees & Hammer, PNAS 97:11262, 2000) with deformable cells (Jadhav, Eggleton &
// Konstantopoulos, Biophys J 88:96, 2005).
//
// Units are those of the capillary number Ca = mu k a / G: lengths in cell radii a, forces
// in G a, energies in G a^2, times in 1/k (k the shear rate), so rates are in units of k;
// a density per area is per a^2, a spring constant is in G (force per length).
#include "capsula/adhesion/WallPlane.hpp"

#include <Teuchos_ParameterList.hpp>

#include <cstdint>
#include <limits>
#include <string>

namespace capsula::adhesion {

/// How a bond's off-rate (and on-rate) depends on its stretch (BondKinetics.hpp).
enum class BondModel {
  Slip,     ///< Bell (1978): k_off = k_off0 exp(gamma |F| / kT)
  CatchSlip ///< Dembo et al. (1988): k_off = k_off0 exp((sigma - sigma_ts) (L - lambda)^2 / (2 kT))
};

/// How bonds form and break.
enum class BondKinetics {
  Stochastic, ///< Monte Carlo per receptor: the exact two-state chain over each step
  MeanField   ///< the expected bond occupancy per receptor, deterministic
};

/// A rectangle x in [xMin, xMax], z in [zMin, zMax] of the ligand wall (infinite bounds:
/// the whole plane). In a periodic box (periodX, periodZ > 0) a point is first moved by the
/// lattice into [0, L_x) x [0, L_z), where a bounded rectangle lies: the ligands repeat with
/// the box.
struct WallRectangle {
  double xMin = -std::numeric_limits<double>::infinity();
  double xMax = std::numeric_limits<double>::infinity();
  double zMin = -std::numeric_limits<double>::infinity();
  double zMax = std::numeric_limits<double>::infinity();
  double periodX = 0.0; ///< L_x of the periodic box (0: x not periodic)
  double periodZ = 0.0; ///< L_z of the periodic box (0: z not periodic)
  bool contains(double x, double z) const;
  bool bounded() const;
};

/// Which wall carries the ligands.
enum class LigandWallChoice {
  Lower, ///< the wall y = 0
  Upper  ///< a channel's upper wall y = H
};

/// The adhesion model, read from a validated "Adhesion" sublist.
struct AdhesionSettings {
  bool enabled = false;
  double receptorDensity = 50.0;                               ///< receptors per a^2 of reference membrane
  double ligandDensity = 100.0;                                ///< ligands per a^2 of wall
  WallRectangle ligandPatch;                                   ///< where the wall carries ligands
  LigandWallChoice ligandWallChoice = LigandWallChoice::Lower; ///< 'Ligand wall'
  WallPlane ligandWall;                                        ///< that wall's plane (the scene sets H for Upper)
  double springConstant = 10.0;                                ///< sigma / G
  double equilibriumLength = 0.02;                             ///< lambda / a
  double reactionDistance = 0.05;        ///< r_0 / a: a receptor binds only within r_0 of the wall
  double patchRadius = 0.0;              ///< rho / a: the membrane patch a bond pulls on (0: a point)
  double onRate = 0.1;                   ///< k_on0 / (k a^2): the forward rate per unit ligand density
  double offRate = 1.0;                  ///< k_off0 / k
  double reactiveCompliance = 1e-3;      ///< gamma / a (Bell)
  double transitionSpringConstant = 9.0; ///< sigma_ts / G (Dembo)
  double thermalEnergy = 1e-4;           ///< k_B T / (G a^2)
  BondModel model = BondModel::Slip;
  BondKinetics kinetics = BondKinetics::Stochastic;
  std::uint64_t seed = 1;
};

/// Declares Enabled, Ligand wall, Receptor density, Ligand density, Ligand patch, Spring constant,
/// Equilibrium length, Reaction distance, Patch radius, On-rate, Off-rate, Reactive compliance, Transition
/// spring constant, Thermal energy, Bond model, Kinetics and Seed.
void declareAdhesionParameters(Teuchos::ParameterList& adhesion);

/// Reads a validated sublist. `path` names it in messages ("Adhesion"); `wall` is the part
/// of the wall the scene simulates (default: the whole plane). Throws core::InputError,
/// naming the key, for a negative density, a spring constant of 0 or a non-positive thermal
/// energy with adhesion enabled, or a ligand patch that is empty or reaches off `wall`.
AdhesionSettings readAdhesionParameters(const Teuchos::ParameterList& adhesion, const std::string& path = "Adhesion",
                                        const WallRectangle& wall = {});

/// The plane of the ligand wall in a domain whose upper wall, if any, is at `channelHeight`
/// (0: none). Throws core::InputError naming 'Adhesion/Ligand wall' for Upper without a
/// channel.
WallPlane ligandWallPlane(LigandWallChoice choice, double channelHeight);

/// "Slip (Bell)" / "Catch-slip (Dembo)", "Stochastic" / "Mean field": the deck's names.
std::string to_string(BondModel model);
std::string to_string(BondKinetics kinetics);

} // namespace capsula::adhesion
