#pragma once
// Integral measures of a closed mesh: element areas, surface area, enclosed volume,
// centroid, reduced volume, projected areas (thesis Section 3.11, ERRATA).
//
// numQuadraturePoints is the thesis's N_Q, the number of points of the triangle rule
// (1, 3, 4, 6, 7, 12 or 13; degrees 1..7). Where an integrand is a polynomial over
// the quadratic element the default rule integrates it exactly, so the result is the
// exact measure of the discrete surface; the degree is given with each function.
#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/mesh/Vec3.hpp>

#include <vector>

namespace capsula::mesh {

/// Area of every element, int_E h_s dxi deta (h_s is not polynomial: not exact).
std::vector<double> elementAreas(const SurfaceMesh& mesh, int numQuadraturePoints = 7);
/// The same for another configuration, `positions` numbered as the mesh's nodes.
std::vector<double> elementAreas(const SurfaceMesh& mesh, const double* positions, int numQuadraturePoints = 7);

double surfaceArea(const SurfaceMesh& mesh, int numQuadraturePoints = 7);

/// V = 1/3 int_S x . n dS (divergence theorem). x . (x_xi cross x_eta) has degree 4,
/// so N_Q >= 6 gives the exact volume enclosed by the discrete surface.
double enclosedVolume(const SurfaceMesh& mesh, int numQuadraturePoints = 6);

/// Volume centroid x_c,i = 1/(2V) int_S x_i^2 n_i dS (eq 3.54 in the general form
/// of the ERRATA; the printed 3/(8 pi) holds only for V = 4 pi / 3). The integrand has
/// degree 6: N_Q >= 12 is exact for the discrete surface.
Vec3 centroid(const SurfaceMesh& mesh, int numQuadraturePoints = 12);

/// Reduced volume nu = (4 pi)^(3/2) / (4 pi / 3) * V / S^(3/2) = 6 sqrt(pi) V / S^(3/2)
/// (eqs 2.6, 5.1): 1 for a sphere, less for any other shape.
double reducedVolume(double area, double volume);
double reducedVolume(const SurfaceMesh& mesh, int numQuadraturePoints = 7);

/// Projected areas on the three coordinate planes: component i is the area of the
/// shadow on the plane normal to e_i, 1/2 int_S |n . e_i| dS for a closed surface
/// (eq 3.56 as corrected in the ERRATA). So [0] is the yz-plane, [2] the xy-plane.
/// |n_i| has a kink where n_i changes sign: convergence in N_Q is slow there.
Vec3 projectedAreas(const SurfaceMesh& mesh, int numQuadraturePoints = 7);

} // namespace capsula::mesh
