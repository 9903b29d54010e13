#include "capsula/adhesion/AdhesionParameters.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>

#include <Teuchos_Array.hpp>

#include <cmath>

namespace capsula::adhesion {

namespace core = capsula::core;

namespace {

const char* const slipName = "Slip (Bell)";
const char* const catchSlipName = "Catch-slip (Dembo)";
const char* const stochasticName = "Stochastic";
const char* const meanFieldName = "Mean field";
const char* const lowerWallName = "Lower";
const char* const upperWallName = "Upper";

void declareDensitiesAndPatch(Teuchos::ParameterList& list)
{
  core::declareReal(list, "Receptor density", 50.0,
                    "Receptors per unit reference membrane area, in 1/a^2 (a the cell radius): each "
                    "element carries density x its reference area of them, placed at material points "
                    "(50 puts ~630 on a sphere of radius a). At most as many as fit in the "
                    "machine's memory and in a receptor index (2^31 - 1) over the cells' reference area.",
                    core::atLeast(0.0));
  core::declareReal(list, "Ligand density", 100.0,
                    "Ligands per unit wall area, in 1/a^2. The forward rate of a receptor within reach "
                    "is 'On-rate' x this density (Hammer & Apte 1992: k_f0 = k_+ n_L; the ligands are "
                    "taken as dense enough that bonds do not deplete them).",
                    core::atLeast(0.0));
  core::declareRealArray(list, "Ligand patch", {}, 0,
                         "The ligand-coated part of the ligand wall ('Ligand wall'): {x_min, x_max, z_min, "
                         "z_max} in cell radii, or empty {} for the whole wall. It must lie on the simulated "
                         "wall and have x_min < x_max, z_min < z_max; in a periodic box it lies within one "
                         "box, [0, L_x] x [0, L_z], and repeats with it.");
}

void declareBondMechanics(Teuchos::ParameterList& list)
{
  core::declareReal(list, "Spring constant", 10.0,
                    "sigma / G: the bond's spring constant over the membrane shear modulus (a bond "
                    "of length L pulls with |F| = sigma |L - lambda|, in units of G a). Must be > 0 "
                    "with adhesion enabled.",
                    core::atLeast(0.0));
  core::declareReal(list, "Equilibrium length", 0.02,
                    "lambda / a: the unstressed bond length, in cell radii (20 nm on a 1 um cell "
                    "is 0.02). At most 'Reaction distance' and, with contact, 'Contact/Range'.",
                    core::atLeast(0.0));
  core::declareReal(list, "Reaction distance", 0.05,
                    "r_0 / a: a free receptor can bind only while its height above the wall is at "
                    "most r_0; the bond forms to the ligand directly below it (Hammer & Apte 1992). "
                    "Also the reach that defines the contact area of the outputs.",
                    core::greaterThan(0.0));
  core::declareReal(list, "Patch radius", 0.0,
                    "rho / a: each receptor is a patch of membrane of this radius around its point "
                    "(on the unstressed shape): the bond pulls at the weighted mean of the 7-point "
                    "quadrature points within rho, weights w_q h_s (1 - r^2 / rho^2)^2, and its force "
                    "is shared by them, as a tether's foot. 0: a point, its force on its element's "
                    "six nodes. A patch must hold at least three quadrature points, and its pulling "
                    "point lie less than 'Reaction distance' - 'Equilibrium length' inside the "
                    "unstressed membrane (on a sphere of radius R the depth is about rho^2 / (8 R)).",
                    core::atLeast(0.0));
  core::declareReal(list, "Thermal energy", 1e-4,
                    "k_B T / (G a^2): the thermal energy over the membrane's energy scale. Sets how "
                    "strongly stretch changes the rates (BondKinetics.hpp).",
                    core::greaterThan(0.0));
}

void declareRates(Teuchos::ParameterList& list)
{
  core::declareReal(list, "On-rate", 0.1,
                    "k_on0 / (k a^2): the unstressed forward rate per unit ligand density, in units "
                    "of the shear rate k times a^2, so k_on0 x 'Ligand density' is the binding rate "
                    "of a receptor at the bond's rest length from the wall, in units of k.",
                    core::atLeast(0.0));
  core::declareReal(list, "Off-rate", 1.0,
                    "k_off0 / k: the unstressed off-rate over the shear rate (the abscissa of the "
                    "Chang-Tees-Hammer state diagram).",
                    core::atLeast(0.0));
  core::declareReal(list, "Reactive compliance", 1e-3,
                    "gamma / a: Bell's reactive compliance (a length: the bond's off-rate grows as "
                    "exp(gamma |F| / k_B T), |F| = sigma |L - lambda|; the ordinate of the "
                    "Chang-Tees-Hammer state diagram). Used by 'Bond model' = 'Slip (Bell)'.",
                    core::atLeast(0.0));
  core::declareReal(list, "Transition spring constant", 9.0,
                    "sigma_ts / G: Dembo's transition-state spring constant. k_off = k_off0 exp((sigma "
                    "- sigma_ts)(L - lambda)^2 / (2 k_B T)): sigma_ts < sigma a slip bond, = sigma an "
                    "ideal one, > sigma a catch bond. Used by 'Bond model' = 'Catch-slip (Dembo)'.",
                    core::atLeast(0.0));
}

void require(bool condition, const std::string& path, const std::string& key, const std::string& why)
{
  core::require<core::InputError>(condition, "'", path, "/", key, "' ", why);
}

WallRectangle readPatch(const Teuchos::ParameterList& list, const std::string& path, const WallRectangle& wall)
{
  const auto& values = list.get<Teuchos::Array<double>>("Ligand patch");
  if (values.empty()) {
    return wall;
  }
  require(
      values.size() == 4, path, "Ligand patch",
      core::message("has ", values.size(), " entries: give {x_min, x_max, z_min, z_max}, or {} for the whole wall."));
  for (const double v : values) {
    require(std::isfinite(v), path, "Ligand patch", "has an entry that is not finite.");
  }
  const WallRectangle patch{values[0], values[1], values[2], values[3]};
  require(patch.xMin < patch.xMax && patch.zMin < patch.zMax, path, "Ligand patch",
          core::message("= {", patch.xMin, ", ", patch.xMax, ", ", patch.zMin, ", ", patch.zMax,
                        "} is empty: it needs x_min < x_max and z_min < z_max."));
  require(patch.xMin >= wall.xMin && patch.xMax <= wall.xMax && patch.zMin >= wall.zMin && patch.zMax <= wall.zMax,
          path, "Ligand patch",
          core::message("= {", patch.xMin, ", ", patch.xMax, ", ", patch.zMin, ", ", patch.zMax,
                        "} reaches off the simulated wall x in [", wall.xMin, ", ", wall.xMax, "], z in [", wall.zMin,
                        ", ", wall.zMax, "]: keep it on the wall."));
  return patch;
}

} // namespace

bool WallRectangle::contains(double x, double z) const
{
  if (periodX > 0.0) {
    x -= periodX * std::floor(x / periodX);
  }
  if (periodZ > 0.0) {
    z -= periodZ * std::floor(z / periodZ);
  }
  return x >= xMin && x <= xMax && z >= zMin && z <= zMax;
}

bool WallRectangle::bounded() const
{
  return std::isfinite(xMin) || std::isfinite(xMax) || std::isfinite(zMin) || std::isfinite(zMax);
}

void declareAdhesionParameters(Teuchos::ParameterList& adhesion)
{
  core::declareBool(adhesion, "Enabled", false,
                    "Receptor-ligand bonds between the membrane and the wall y = 0 (Hammer's Adhesive "
                    "Dynamics). Lengths are in cell radii a, forces in G a, times in 1/k, rates in units "
                    "of the shear rate k (the scales of the capillary number).");
  core::declareChoice(adhesion, "Ligand wall", lowerWallName, {lowerWallName, upperWallName},
                      "The wall that carries the ligands: 'Lower', the wall y = 0, or 'Upper', the upper wall "
                      "y = H of a channel ('Wall/Channel height' > 0) in Poiseuille flow (both walls at rest). "
                      "Bonds form to the point of that wall nearest to the receptor; gaps and the reach are "
                      "measured to it.");
  declareDensitiesAndPatch(adhesion);
  declareBondMechanics(adhesion);
  declareRates(adhesion);
  core::declareChoice(adhesion, "Bond model", slipName, {slipName, catchSlipName},
                      "'Slip (Bell)': k_off = k_off0 exp(gamma |F| / k_B T) (Bell, Science 200:618, "
                      "1978), forward rate k_on0 n_L exp(sigma |y| (gamma - |y|/2) / k_B T), y = h - lambda "
                      "(Hammer & Apte 1992). 'Catch-slip (Dembo)': k_off = k_off0 exp((sigma - sigma_ts) "
                      "y^2 / (2 k_B T)), forward rate k_on0 n_L exp(-sigma_ts y^2 / (2 k_B T)) (Dembo, "
                      "Torney, Saxman & Hammer, Proc R Soc B 234:55, 1988).");
  core::declareChoice(adhesion, "Kinetics", stochasticName, {stochasticName, meanFieldName},
                      "'Stochastic': each receptor follows the two-state chain free <-> bound exactly "
                      "over the step, binding and breaking as often as its rates make it (a bond "
                      "breaks with probability 1 - exp(-k_off dt), a free receptor is bound at the end "
                      "with k_on / (k_on + k_off) (1 - exp(-(k_on + k_off) dt))), from random numbers "
                      "drawn per receptor and step (the same whatever the number of MPI ranks), so the "
                      "bound fraction does not depend on the step. 'Mean field': each receptor carries "
                      "its expected bond occupancy, advanced by the exact solution of dp/dt = k_on (1 "
                      "- p) - k_off p over the step (deterministic). The rates are those at the end of "
                      "the step, held over it.");
  core::declareInt(adhesion, "Seed", 1,
                   "Seed of the receptor placement and of the stochastic kinetics: the same seed "
                   "gives the same receptors and the same bond events.",
                   0);
}

AdhesionSettings readAdhesionParameters(const Teuchos::ParameterList& adhesion, const std::string& path,
                                        const WallRectangle& wall)
{
  AdhesionSettings s;
  s.enabled = adhesion.get<bool>("Enabled");
  s.ligandWallChoice = adhesion.isParameter("Ligand wall") && adhesion.get<std::string>("Ligand wall") == upperWallName
                           ? LigandWallChoice::Upper
                           : LigandWallChoice::Lower;
  s.receptorDensity = adhesion.get<double>("Receptor density");
  s.ligandDensity = adhesion.get<double>("Ligand density");
  s.springConstant = adhesion.get<double>("Spring constant");
  s.equilibriumLength = adhesion.get<double>("Equilibrium length");
  s.reactionDistance = adhesion.get<double>("Reaction distance");
  s.patchRadius = adhesion.get<double>("Patch radius");
  s.onRate = adhesion.get<double>("On-rate");
  s.offRate = adhesion.get<double>("Off-rate");
  s.reactiveCompliance = adhesion.get<double>("Reactive compliance");
  s.transitionSpringConstant = adhesion.get<double>("Transition spring constant");
  s.thermalEnergy = adhesion.get<double>("Thermal energy");
  s.model = adhesion.get<std::string>("Bond model") == catchSlipName ? BondModel::CatchSlip : BondModel::Slip;
  s.kinetics =
      adhesion.get<std::string>("Kinetics") == meanFieldName ? BondKinetics::MeanField : BondKinetics::Stochastic;
  const int seed = adhesion.get<int>("Seed");
  require(seed >= 0, path, "Seed", core::message("= ", seed, " is negative: give a seed >= 0."));
  s.seed = static_cast<std::uint64_t>(seed);

  // The validators check these too; a list built in code has not been through them.
  require(s.receptorDensity >= 0.0, path, "Receptor density",
          core::message("= ", s.receptorDensity, " is negative: give a density >= 0."));
  require(s.ligandDensity >= 0.0, path, "Ligand density",
          core::message("= ", s.ligandDensity, " is negative: give a density >= 0."));
  const std::pair<const char*, double> nonNegative[] = {{"Equilibrium length", s.equilibriumLength},
                                                        {"On-rate", s.onRate},
                                                        {"Off-rate", s.offRate},
                                                        {"Reactive compliance", s.reactiveCompliance},
                                                        {"Transition spring constant", s.transitionSpringConstant},
                                                        {"Patch radius", s.patchRadius}};
  for (const auto& [key, value] : nonNegative) {
    require(value >= 0.0, path, key, core::message("= ", value, " is negative: give a value >= 0."));
  }
  s.ligandPatch = readPatch(adhesion, path, wall);
  if (s.enabled) {
    require(s.springConstant > 0.0, path, "Spring constant",
            core::message("= ", s.springConstant,
                          " with adhesion enabled: a bond needs a spring constant > 0 (or set 'Enabled' = false)."));
    require(s.thermalEnergy > 0.0, path, "Thermal energy",
            core::message("= ", s.thermalEnergy, " with adhesion enabled: the rates need k_B T > 0."));
    require(s.reactionDistance > 0.0, path, "Reaction distance",
            core::message("= ", s.reactionDistance, " with adhesion enabled: give a reach > 0."));
  }
  return s;
}

WallPlane ligandWallPlane(LigandWallChoice choice, double channelHeight)
{
  if (choice == LigandWallChoice::Lower) {
    return WallPlane{0.0, 1};
  }
  core::require<core::InputError>(channelHeight > 0.0,
                                  "'Adhesion/Ligand wall' = Upper, but the domain has no upper wall: set "
                                  "'Wall/Channel height' > 0 for a channel, or put the ligands on the 'Lower' wall.");
  return WallPlane{channelHeight, -1};
}

std::string to_string(BondModel model)
{
  return model == BondModel::CatchSlip ? catchSlipName : slipName;
}

std::string to_string(BondKinetics kinetics)
{
  return kinetics == BondKinetics::MeanField ? meanFieldName : stochasticName;
}

} // namespace capsula::adhesion
