#pragma once
// The tangent stiffness H = d2E/dx dx of a membrane at one configuration, kept as its
// element matrices (MembraneEnergyHessian.hpp) on the mesh's connectivity: applied
// element by element (y = H x, what a Krylov solver needs) or handed over entry by entry
// to assemble a sparse matrix (what a preconditioner needs). H is symmetric, sparse (a
// node couples to the nodes of its elements) and, at a stable state, positive
// semi-definite with the rigid motions in its kernel.
#include "capsula/elasticity/MembraneEnergyHessian.hpp"

#include <capsula/mesh/SurfaceMesh.hpp>

#include <vector>

namespace capsula::elasticity {

class TangentStiffness {
public:
  /// `mesh` gives the connectivity (it must outlive this object); one matrix per element.
  TangentStiffness(const mesh::SurfaceMesh& mesh, std::vector<ElementStiffness> elements);

  int numNodes() const { return mesh_->numNodes(); }
  const std::vector<ElementStiffness>& elements() const { return elements_; }

  /// y = H x for x, y with 3 entries per node (y is overwritten).
  void apply(const double* x, double* y) const;

  /// Calls add(row, column, value) for every entry of every element matrix, rows and
  /// columns numbered 3 node + coordinate; entries of shared nodes come once per element
  /// and are to be summed.
  template <class Add>
  void forEachEntry(Add&& add) const
  {
    for (std::size_t e = 0; e < elements_.size(); ++e) {
      const auto& nodes = mesh_->element(static_cast<int>(e));
      const ElementStiffness& K = elements_[e];
      for (int k = 0; k < 6; ++k) {
        for (int i = 0; i < 3; ++i) {
          const int row = 3 * nodes[static_cast<std::size_t>(k)] + i;
          for (int l = 0; l < 6; ++l) {
            for (int j = 0; j < 3; ++j) {
              add(row, 3 * nodes[static_cast<std::size_t>(l)] + j,
                  K[static_cast<std::size_t>((3 * k + i) * 18 + 3 * l + j)]);
            }
          }
        }
      }
    }
  }

private:
  const mesh::SurfaceMesh* mesh_;
  std::vector<ElementStiffness> elements_;
};

} // namespace capsula::elasticity
