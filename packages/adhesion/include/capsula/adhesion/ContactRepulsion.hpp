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
// so no bounded load can push a membrane onto the wall; a mean load pressure P stops it at
// the gap d* with p(d*) = P, about p_0 delta / (P + 2 p_0) (ContactParameters.hpp).
//
// Nodal forces: node k carries the pressure over its share of the membrane, a_k = sum of
// A_e / 6 over its elements (current areas; sum_k a_k is the surface area):
//   wall:  F_k = p(y_k) a_k e_y;
//   cells: node k of one cell against the flat-faceted surface of the other (four flat
//          triangles per 6-node element, as scene/SurfaceGap.hpp), closest point c at gap
//          d: (1/2) p(d) a_k (x_k - c)/d on node k, its opposite on the facet's three nodes
//          with the barycentric weights of c; both cells' nodes are visited, hence the 1/2
//          (each pass carries the pressure over one side's area). Action equals reaction
//          along the line x_k - c, and c is the barycentric combination of the facet's
//          nodes, so the pair's total force and torque vanish to round-off.
// A gap <= 0 (a node through the wall) is evaluated at 1e-6 delta: a huge, finite push back.
#include "capsula/adhesion/ContactParameters.hpp"
#include "capsula/adhesion/LoadStiffness.hpp"

#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/mesh/Vec3.hpp>

#include <array>
#include <vector>

namespace capsula::adhesion {

/// p(gap) in units of G / a.
double repulsionPressure(const ContactSettings& contact, double gap);

/// dp/d(gap), G / a^2: negative below the range, 0 at and beyond it (and below the gap
/// 1e-6 delta, where the pressure is held constant).
double repulsionPressureSlope(const ContactSettings& contact, double gap);

/// a_k = sum over the elements of node k of A_e / 6, at `positions` (3 per node).
std::vector<double> nodalAreaShares(const mesh::SurfaceMesh& mesh, const double* positions);

/// Adds the wall repulsion F_k = p(y_k) a_k e_y to `nodalForces` (3 per node); returns the
/// total. `areas` from nodalAreaShares at the same positions.
mesh::Vec3 addWallContactForces(const ContactSettings& contact, const mesh::SurfaceMesh& mesh, const double* positions,
                                const std::vector<double>& areas, double* nodalForces);

/// Adds the stiffness of the wall repulsion at fixed area shares, -dF_k,y/dy_k = -p'(y_k) a_k
/// (>= 0, on the diagonal), to `stiffness`. How a_k changes with the nodes is left out: it is
/// of the size of the force itself and does not make the motion stiff.
void addWallContactStiffness(const ContactSettings& contact, const mesh::SurfaceMesh& mesh, const double* positions,
                             const std::vector<double>& areas, LoadStiffness& stiffness);

/// Adds the repulsion between cells A and B to their nodal forces (3 per node each); returns
/// the total force on A (the one on B is its opposite). Nodes farther than the range from
/// the other cell's bounding box are skipped, so cells apart cost two bounding boxes.
mesh::Vec3 addCellContactForces(const ContactSettings& contact, const mesh::SurfaceMesh& a, const double* xa,
                                const std::vector<double>& areasA, double* forcesA, const mesh::SurfaceMesh& b,
                                const double* xb, const std::vector<double>& areasB, double* forcesB);

/// The closest point of the flat triangle (p0, p1, p2) to x, as barycentric weights w
/// (c = w0 p0 + w1 p1 + w2 p2, each w >= 0, sum 1).
std::array<double, 3> closestBarycentric(const mesh::Vec3& x, const mesh::Vec3& p0, const mesh::Vec3& p1,
                                         const mesh::Vec3& p2);

} // namespace capsula::adhesion
