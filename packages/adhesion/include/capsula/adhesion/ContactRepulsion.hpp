#pragma once
// Short-range contact repulsion between a membrane and the wall y = 0, and between the
// membranes of two cells, as nodal forces.
//
// Pressure: the steric repulsion of a compressed glycocalyx, p = p_0 / (exp(d / delta) - 1)
// (Bongrand & Bell 1984, as used by Hammer & Apte 1992 in Adhesive Dynamics: F_0 tau e^(-tau
// d) / (1 - e^(-tau d)) with tau = 1 / delta), shifted so that it and its slope vanish at
// the range delta (the shifted-force truncation of molecular dynamics):
//   p(d) = p_0 [g(d/delta) - g(1) - (d/delta - 1) g'(1)],  g(s) = 1 / (e^s - 1),  d < delta;
//   p(d) = 0 for d >= delta.
// g is convex and decreasing, so p > 0, p' < 0 below delta and p = p' = 0 at delta (C1). As
// d -> 0, p ~ p_0 delta / d - 2 p_0: the work to close the gap diverges (logarithmically),
// so no bounded load can push a flat membrane onto the wall; a mean load pressure P stops it
// at the gap d* with p(d*) = P, about p_0 delta / (P + 2 p_0) (ContactParameters.hpp). On a
// rigid sphere of radius R the total force grows only as 2 pi R p_0 delta ln(delta / d).
//
// Nodal forces, two ways ('Load', ContactParameters.hpp; 'Nodal area' by default).
// 'Virtual work': the virtual work of the pressure over the membrane, F_k = int_S phi_k p dS
// times the direction of the push, as the membrane's own F_k = dE/dx_k and the bonds' point
// forces (PointForces.hpp): the mass solve of the load (elasticity MembraneMechanics) then
// turns them into a load density equal to p where the mesh resolves it. (Lumped shares of
// A_e / 6 per node are not such a load: for a uniform p on flat quadratic elements the
// density they give is 8.5 p at the vertices and p at the midside nodes, a grid-scale
// oscillation of the load where the membrane is pressed.) The integrals use the 7-point
// rule on the 64 triangles that split each element (m = 8 per side), since the pressure
// changes over a fraction of an element:
//   wall:  F_k = int_S phi_k p(y) dS e_y over the elements that can reach the range;
//   cells: at each point x_q (weight w_q h_s, the 7-point rule on 4 pieces) of one cell, the
//          closest point c of the other cell's flat-faceted surface (four flat triangles per
//          6-node element, as scene/SurfaceGap.hpp) at gap d: (1/2) p(d) w_q h_s (x_q - c)/d
//          spread by phi_k(x_q) onto the point's element, its opposite on the facet's three
//          nodes with the barycentric weights of c; both cells' points are visited, hence the
//          1/2 (each pass carries the pressure over one side's area). Action equals reaction
//          along the line x_q - c; x_q = sum_k phi_k x_k and c is the barycentric combination
//          of the facet's nodes, so the pair's total force and torque vanish to round-off.
// 'Nodal area' takes node k with its share a_k instead of the points: F_k = p(y_k) a_k e_y,
// and against a cell (1/2) p(d) a_k (x_k - c)/d.
// A gap <= 0 (a point through the wall) is evaluated at 1e-6 delta: a huge, finite push back.
#include "capsula/adhesion/ContactParameters.hpp"
#include "capsula/adhesion/LoadStiffness.hpp"
#include "capsula/adhesion/WallPlane.hpp"

#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/mesh/Vec3.hpp>

#include <array>
#include <vector>

namespace capsula::adhesion {

/// A no-slip plane that repels membranes on its fluid side (WallPlane.hpp).
using ContactWall = WallPlane;

/// p(gap) in units of G / a.
double repulsionPressure(const ContactSettings& contact, double gap);

/// dp/d(gap), G / a^2: negative below the range, 0 at and beyond it (and below the gap
/// 1e-6 delta, where the pressure is held constant).
double repulsionPressureSlope(const ContactSettings& contact, double gap);

/// a_k = sum over the elements of node k of A_e / 6, at `positions` (3 per node): a
/// partition of the area for measures (the contact area), not a load.
std::vector<double> nodalAreaShares(const mesh::SurfaceMesh& mesh, const double* positions);

/// Adds the repulsion of `wall`, F_k = int_S phi_k p(g) dS s e_y (g the gap, s the wall's
/// fluid side), to `nodalForces` (3 per node); returns the total, int_S p dS s e_y.
mesh::Vec3 addWallContactForces(const ContactSettings& contact, const mesh::SurfaceMesh& mesh, const double* positions,
                                double* nodalForces, const ContactWall& wall = {});

/// Adds the stiffness of the repulsion of `wall`, -dF_k,y/dy_l = -int_S phi_k phi_l p'(g) dS
/// (s^2 = 1)
/// (symmetric, positive semi-definite: p' <= 0), to `stiffness`. How dS and the direction
/// change with the nodes is left out: it is of the size of the force itself and does not
/// make the motion stiff.
void addWallContactStiffness(const ContactSettings& contact, const mesh::SurfaceMesh& mesh, const double* positions,
                             LoadStiffness& stiffness, const ContactWall& wall = {});

/// Adds the repulsion between cells A and B to their nodal forces (3 per node each); returns
/// the total force on A (the one on B is its opposite). Elements farther than the range from
/// the other cell's bounding box are skipped, so cells apart cost two bounding boxes.
mesh::Vec3 addCellContactForces(const ContactSettings& contact, const mesh::SurfaceMesh& a, const double* xa,
                                double* forcesA, const mesh::SurfaceMesh& b, const double* xb, double* forcesB);

/// The closest point of the flat triangle (p0, p1, p2) to x, as barycentric weights w
/// (c = w0 p0 + w1 p1 + w2 p2, each w >= 0, sum 1).
std::array<double, 3> closestBarycentric(const mesh::Vec3& x, const mesh::Vec3& p0, const mesh::Vec3& p1,
                                         const mesh::Vec3& p2);

} // namespace capsula::adhesion
