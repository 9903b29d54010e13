#pragma once
// Unit normals at the nodes. The mesh is only C0, so each element gives its own
// normal at a shared node; the thesis (Section 3.5.2) averages them weighted by
// the areas of the elements that share the node.
#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/mesh/Vec3.hpp>

#include <vector>

namespace capsula::mesh {

/// n_node = normalise( sum_e A_e n_e(node) ), n_e(node) the element's unit normal at
/// the node's parametric point, A_e the element area (N_Q-point rule).
std::vector<Vec3> nodeNormals(const SurfaceMesh& mesh, int numQuadraturePoints = 7);
/// The same for another configuration, `positions` numbered as the mesh's nodes.
std::vector<Vec3> nodeNormals(const SurfaceMesh& mesh, const double* positions, int numQuadraturePoints = 7);

} // namespace capsula::mesh
