#pragma once
// Force-dependent rates of receptor-ligand bonds (Adhesive Dynamics, Hammer & Apte 1992).
//
// A bond is a linear spring of constant sigma and rest length lambda; at length L it pulls
// with |F| = sigma |L - lambda|. With y = L - lambda (for a free receptor at height h above
// the wall, y = h - lambda: the length the bond would have if it formed now):
//   Slip (Bell 1978):        k_off = k_off0 exp(gamma |F| / kT)
//                            k_on  = k_on0 n_L exp(sigma |y| (gamma - |y|/2) / kT)
//   Catch-slip (Dembo 1988): k_off = k_off0 exp((sigma - sigma_ts) y^2 / (2 kT))
//                            k_on  = k_on0 n_L exp(-sigma_ts y^2 / (2 kT))
// In both, k_on / k_off = (k_on0 n_L / k_off0) exp(-sigma y^2 / (2 kT)): the ratio is the
// Boltzmann factor of the stretched spring (detailed balance, Dembo et al. 1988), which is
// how the Bell on-rate follows from the Bell off-rate (the form of Hammer & Apte 1992 and
// Chang, Tees & Hammer 2000). k_on is zero beyond the reaction distance r_0 and off the
// ligand patch. Exponents are capped at 700 so a rate is huge, never infinite.
#include "capsula/adhesion/AdhesionParameters.hpp"

namespace capsula::adhesion {

/// k_off of a bond of length `length` (units of the shear rate).
double offRate(const AdhesionSettings& s, double length);

/// k_on of a free receptor at the gap `height` from the ligand wall whose foot (x, z) is on
/// the ligand patch (0 if it is farther than the reaction distance, through the wall, or off
/// the patch).
double onRate(const AdhesionSettings& s, double height, double x, double z);

/// 1 - exp(-rate dt): the probability that a Poisson event of the given rate happens within
/// dt (a bond's breakage within a step).
double eventProbability(double rate, double dt);

/// The probability that a receptor free at the start of an interval dt is bound at its end,
/// for the two-state chain free <-> bound of constant rates k_on, k_off:
///   P = k_on / (k_on + k_off) (1 - exp(-(k_on + k_off) dt)),
/// binding and breaking as often as the rates make them within dt (exact for any k dt; the
/// bound fraction of a clamped population settles at k_on / (k_on + k_off) for every step).
double bindingProbability(double onRate, double offRate, double dt);

/// The time at which a bond of off-rate `rate` breaks, given the draw u in [0, 1) that
/// broke it within the step (u < eventProbability(rate, dt)): the inverse of the
/// exponential law's distribution, -ln(1 - u) / rate, in [0, dt).
double breakageTime(double rate, double u);

/// |F| = sigma |L - lambda|, the magnitude of the bond's spring force.
double bondForceMagnitude(const AdhesionSettings& s, double length);

} // namespace capsula::adhesion
