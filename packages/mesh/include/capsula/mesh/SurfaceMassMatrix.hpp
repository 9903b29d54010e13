#pragma once
// The consistent mass matrix of a quadratic surface mesh, M_kl = int_S phi_k phi_l dS,
// and the solve M f = F that turns nodal forces (virtual work: F_k = int_S phi_k f dS)
// into the nodal values of the density f they come from.
//
// M is symmetric positive definite. Row sums are the nodal areas int_S phi_k dS, which
// for quadratic triangles are zero at the vertices of a flat element, so M cannot be
// lumped (a lumped P2 mass matrix is singular); it is solved by conjugate gradients with
// a Jacobi preconditioner instead: its condition number does not grow with refinement
// (about 20-40 on an icosphere), so a few tens of iterations reach round-off.
//
// The element matrices are stored (21 numbers per element); assemble() refreshes them
// for new positions, which costs one pass of the 7-point rule over the elements.
#include <capsula/mesh/SurfaceMesh.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace capsula::mesh {

class SurfaceMassMatrix {
public:
  /// The topology of `mesh` (it must outlive this object; its positions are not used).
  explicit SurfaceMassMatrix(const SurfaceMesh& mesh);

  /// Element matrices at `positions` (3 per node), each element with its own shape
  /// parameters (eq 3.17), the 7-point rule (exact for the degree-4 product phi_k phi_l
  /// on a flat element).
  void assemble(const double* positions);
  /// The same with given shape parameters per element (numElements entries), e.g. those of
  /// a reference shape: with them fixed the element map is linear in the nodal positions,
  /// which is what an energy differentiated node by node needs (elasticity::HelfrichBending).
  void assemble(const double* positions, const std::vector<ShapeParameters>& parameters);

  /// The 6x6 element matrix of element e (row-major, local node order), after assemble().
  const std::array<double, 36>& elementMatrix(int e) const { return element_[static_cast<std::size_t>(e)]; }

  /// y = M x for 3 components per node (x and y hold 3 * numNodes doubles).
  void apply(const double* x, double* y) const;

  /// Solves M f = F (3 components per node) to a relative residual `tolerance` in the
  /// max norm of each component. Returns the number of iterations. Throws
  /// core::NumericalError if it does not converge in 500 iterations (a degenerate mesh).
  int solve(const double* F, double* f, double tolerance = 1e-13);

  /// int_S phi_k dS per node: the row sums.
  std::vector<double> nodalAreas() const;
  /// The same into `areas` (numNodes doubles), without allocating.
  void nodalAreas(double* areas) const;

private:
  void assembleElement(int e, const ElementNodes& x, const ShapeParameters& p);

  const SurfaceMesh* mesh_;
  std::vector<std::array<double, 36>> element_; // full 6x6 element matrices
  std::vector<double> diagonal_;
  // CG work arrays.
  std::vector<double> r_, z_, p_, q_;
};

} // namespace capsula::mesh
