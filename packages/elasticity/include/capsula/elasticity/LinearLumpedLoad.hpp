#pragma once
// The load density of the bending forces: nodal virtual-work forces restricted to the
// linear (vertex) space and divided by its lumped mass.
//
// The bending forces F_k = dE/dx_k of HelfrichBending converge to the exact load only
// weakly: M^-1 F, the density the membrane's strain forces use, carries an O(1) grid-scale
// mode between vertex and midside nodes (the O(h^2) error of the vertex curvature seen
// through the two derivatives the load takes of it), and its single layer converges at
// first order at best (docs/membrane-forces.md, "Bending"). The linear hat function of
// vertex v is psi_v = phi_v + (phi_m1 + ... )/2 over its midside neighbours m, exactly,
// so its virtual work is F^1_v = F_v + sum_m F_m / 2; with the lumped linear mass
// A^1_v = int psi_v dA = a_v + sum_m a_m / 2 > 0 (a_k = int phi_k dA) the density is
//   f_v = F^1_v / A^1_v   at the vertices,   f_m = (f_v1 + f_v2) / 2   at midside nodes,
// the linear interpolant. Total force is kept exactly (sum_v A^1_v f_v = sum_k F_k), and
// the vertex/midside mode, which the restriction averages out, is gone.
#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/mesh/Vec3.hpp>

#include <vector>

namespace capsula::elasticity {

class LinearLumpedLoad {
public:
  /// The topology of `mesh` (it must outlive this object).
  explicit LinearLumpedLoad(const mesh::SurfaceMesh& mesh);

  /// f from the nodal forces F (both 3 numbers per node) and the quadratic nodal areas
  /// a_k = int phi_k dA (mesh::SurfaceMassMatrix row sums). Adds into f when `add` is
  /// true. No allocation.
  void apply(const double* F, const double* areas, double* f, bool add = false);

private:
  const mesh::SurfaceMesh* mesh_;
  std::vector<int> vertices_;     // the nodes that are element vertices
  std::vector<mesh::Vec3> force_; // F^1_v, per node (vertices used)
  std::vector<double> area_;      // A^1_v, per node (vertices used)
};

} // namespace capsula::elasticity
