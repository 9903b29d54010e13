#pragma once
// The mean (x-z averaged) disturbance flow of the cells in a channel periodic along x and z,
// as moments of the membrane load and of the double-layer density over the surfaces.
//
// In the channel 0 < y < H, the zero mode of the Stokeslet is the flow of a uniform sheet of
// force, mu u'' = -(g / A) delta(y - h) with no slip on both walls (docs/domains.md, "The zero
// mode"), and the double layer, a distribution of stresslets of strength (1 - lambda) mu
// (u_x n_y + u_y n_x) in the x-y plane, drives the y-derivative of it in the source height.
// A quantity linear in the mean flow u_bar(y) whose value for a sheet of unit force at height
// h is W(h) / A (A = L_x L_z) is therefore, for the boundary-integral flow of
// BoundaryIntegralSolver.hpp, M[W] / A with
//
//   M[W] = -(1/Ca) sum_c int_Sc Delta f_x W(y) dS
//          + sum_c (1 - lambda_c) int_Sc (u_x n_y + u_y n_x) W'(y) dS
//          + sum_c (1 - lambda_c) (-W'') int_Sc (x - x_c) (u . n) dS,
//
// The last term counts the cells' insides, where the representation above gives lambda_c
// times the velocity (Pozrikidis 1992, eq 5.3.7): the x-z average of the representation is
// not the mean of the velocity across a cell, and a quantity that integrates the mean flow
// over heights the cells occupy (the flux, -W'' = 1) gets (1 - lambda_c) times the cell's
// int u_x dV = int_Sc (x - x_c) (u . n) dS back (x_c any point: int u . n dS = 0 for the
// incompressible inside). Quantities taken at the walls (-W'' = 0 between them) need no such
// term. For example the flux through a cross-section x = const (W = y (H - y) / 2, times L_z, so
// Q' = M / L_x) or the mean of du/dy on the two walls (W = 1/2 - y / H).
// docs/suspensions.md, "Relative viscosity", states the derivation; the weights' names below
// say which quantity each gives.
//
// Integrated with the regular triangle rule of `quadraturePoints` points over the curved
// 6-node elements, the load and the velocity interpolated with the shape functions as the
// single and double layers interpolate them (eqs 3.36, 3.44).
#include <capsula/operators/CellSurfaces.hpp>
#include <capsula/operators/LoadDensity.hpp>

#include <functional>

namespace capsula::operators {

/// A weight W(y) over the wall-normal coordinate, its derivative W'(y), and -W'' where the
/// quantity integrates the mean flow across the cells (the interior term below).
struct WallNormalWeight {
  std::function<double(double)> value;
  std::function<double(double)> slope;
  double interior = 0.0;
};

/// The flux through a cross-section x = const per unit length along z, W = (y - y0) (H -
/// (y - y0)) / 2 for the channel y0 < y < y0 + H (divide M by L_x for the flux through the
/// whole cross-section of width L_z).
WallNormalWeight crossSectionFluxWeight(double lowerWall, double height);
/// The mean of du/dy on the two walls (plane Couette flow's shear rate on both), W = 1/2 -
/// (y - y0) / H.
WallNormalWeight meanWallShearRateWeight(double lowerWall, double height);

/// M[W] of the equation above. `nodeVelocities` (3 per node, global numbering) may be null
/// when every viscosity ratio is 1.
double streamwiseMoment(const CellSurfaces& surfaces, const LoadDensity& load, const double* nodeVelocities,
                        double capillaryNumber, const WallNormalWeight& weight, int quadraturePoints = 7);

} // namespace capsula::operators
