#pragma once
// Point forces on a membrane as the nodal forces of virtual work.
//
// A force F at the material point x(xi, eta) of element e does work F . dx(xi, eta) =
// sum_k phi_k(xi, eta) F . dx_k under a virtual displacement of the nodes, so its nodal
// forces are F_k = phi_k(xi, eta) F on the element's six nodes: the same kind of load as
// the membrane's F_k = dE/dx_k (elasticity/MembraneMechanics.hpp, VirtualWork), which the
// mass solve turns into a load density f with int phi_k f dA = F_k. Since sum_k phi_k = 1
// and sum_k phi_k x_k = x(xi, eta) (isoparametric map), sum_k F_k = F and
// sum_k x_k x F_k = x(xi, eta) x F: the total force and the torque about any point are
// those of the point force, to round-off.
#include <capsula/mesh/ShapeFunctions.hpp>
#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/mesh/Vec3.hpp>

namespace capsula::adhesion {

/// Adds phi_k(xi, eta) F to the nodal forces of the six nodes of element e.
/// `nodalForces` holds 3 doubles per node of `mesh`; `parameters` are the element's shape
/// parameters (the reference ones for a material point).
void spreadPointForce(const mesh::SurfaceMesh& mesh, int element, const mesh::ShapeParameters& parameters, double xi,
                      double eta, const mesh::Vec3& force, double* nodalForces);

/// The same with the weights phi[6] already evaluated.
void spreadPointForce(const mesh::ElementConnectivity& nodes, const double phi[6], const mesh::Vec3& force,
                      double* nodalForces);

} // namespace capsula::adhesion
