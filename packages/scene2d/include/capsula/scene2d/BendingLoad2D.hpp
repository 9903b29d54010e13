#pragma once
// Load of a 2D membrane's bending stiffness on the fluids: a beam-like bending moment
// m = k_b (kappa - kappa_ref) with the energy (k_b / 2) oint (kappa - kappa_ref)^2 dl, per unit
// length of the contour (the 2D elastica; e.g. the 2D capsules of Pozrikidis (ed.), Modeling
// and Simulation of Capsules and Biological Cells, 2003).
//
// Sign convention: that of MembraneLoad2D.hpp, Delta f = (sigma_ext - sigma_int) . n, n
// outward. There the tension's load gamma kappa n - (d gamma/dl) t is the variational
// derivative of the stored energy, dE = oint Delta f . delta x dl: with delta x = psi n + phi t,
// d(dl) = (kappa psi + d phi/dl) dl gives oint gamma d(dl) = oint (gamma kappa psi -
// (d gamma/dl) phi) dl. The bending load is that derivative of the bending energy.
//
// Derivation (closed contour, capsula::contour conventions dt/dl = -kappa n, dn/dl = kappa t;
// kappa_ref attached to the material points; q = kappa - kappa_ref). A displacement
// delta x = psi n + phi t changes the curvature at a material point by
//     delta kappa = -d^2 psi/dl^2 - kappa^2 psi + phi d kappa/dl
// (a circle pushed out by psi has 1/(R + psi)), and the length element by
// (kappa psi + d phi/dl) dl. Varying (k_b/2) oint q^2 dl and integrating by parts twice:
//     dE = k_b oint { psi [-q'' - kappa^2 q + kappa q^2 / 2] + phi q d kappa_ref/dl } dl,
// so, with kappa^2 q - kappa q^2 / 2 = q kappa (kappa + kappa_ref) / 2 = kappa (kappa^2 -
// kappa_ref^2) / 2,
//     Delta f_b = -k_b [ d^2 q/dl^2 + q kappa (kappa + kappa_ref) / 2 ] n + k_b q (d kappa_ref/dl) t.
// With kappa_ref = 0 it is the elastica's -k_b (kappa'' + kappa^3 / 2) n. A circle of radius R
// (E = pi k_b / R, dE/dR = -pi k_b / R^2) gets Delta f_b = -k_b / (2 R^3) n: pointing into the
// cell, so the single layer (velocity ~ -Delta f) expands it, as the energy wants; the
// tension's Laplace load gamma / R n of an inflated circle has the opposite sign and
// shrinks it. The tangential part is there only where kappa_ref varies along the contour.
//
// The load is a total derivative (the energy is invariant under rigid motions), so oint
// Delta f_b dl = 0 and its torque vanishes on a closed contour. On a tethered contour the
// integration by parts also leaves the end terms m d psi/dl and (dm/dl) psi at the tether:
// psi = 0 there (the node is held), and the moment m (0+) - m (s_max-) is taken by the
// tether point and is not a load on the fluid.
#include <capsula/contour/Contour.hpp>

#include <Eigen/Core>

namespace capsula::scene2d {

/// Delta f_b at one point: `modulus` k_b, `misfit` q = kappa - kappa_ref, `misfitCurvature`
/// d^2 q / dl^2, `referenceCurvature` kappa_ref and `referenceSlope` d kappa_ref / dl there;
/// kappa, n and t are the point's.
inline Eigen::Vector2d bendingLoad2D(double modulus, double misfit, double misfitCurvature, double referenceCurvature,
                                     double referenceSlope, const contour::ContourPoint& point)
{
  const double kappa = point.curvature;
  const double normal = -modulus * (misfitCurvature + 0.5 * misfit * kappa * (kappa + referenceCurvature));
  return normal * point.normal + (modulus * misfit * referenceSlope) * point.tangent;
}

} // namespace capsula::scene2d
