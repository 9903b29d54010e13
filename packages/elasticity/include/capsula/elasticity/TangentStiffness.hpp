#pragma once
// The tangent stiffness H = d2E/dx dx of a membrane at one configuration, kept as its
// element matrices (MembraneEnergyHessian.hpp) on the mesh's connectivity: applied
// element by element (y = H x, what a Krylov solver needs) or handed over entry by entry
// to assemble a sparse matrix (what a preconditioner needs). H is symmetric, sparse (a
// node couples to the nodes of its elements) and, at a stable state, positive
// semi-definite with the rigid motions in its kernel.
//
// With a bending term (HelfrichBending.hpp) it adds the bending stiffness on the normal
// modes, k_b P K M^-1 K P: exactly in apply(), and in forEachEntry() its sparse version
// with M replaced by a diagonal bound (it couples a node to the nodes two elements away).
#include "capsula/elasticity/HelfrichBending.hpp"
#include "capsula/elasticity/MembraneEnergyHessian.hpp"

#include <capsula/mesh/SurfaceMesh.hpp>

#include <memory>
#include <vector>

namespace capsula::elasticity {

class TangentStiffness {
public:
  /// `mesh` gives the connectivity (it must outlive this object); one matrix per element.
  /// `bending`, if any, linearised at the same positions (its last evaluate()).
  TangentStiffness(const mesh::SurfaceMesh& mesh, std::vector<ElementStiffness> elements,
                   std::shared_ptr<HelfrichBending> bending = nullptr);

  int numNodes() const { return mesh_->numNodes(); }
  const std::vector<ElementStiffness>& elements() const { return elements_; }

  /// y = H x for x, y with 3 entries per node (y is overwritten): the strain energy's
  /// second variation plus the bending stiffness, if any.
  void apply(const double* x, double* y) const;
  bool hasBending() const { return bending_ != nullptr; }

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
    if (bending_) {
      bending_->forEachEntry(add);
    }
  }

private:
  const mesh::SurfaceMesh* mesh_;
  std::vector<ElementStiffness> elements_;
  std::shared_ptr<HelfrichBending> bending_; // its apply needs work arrays: not const
  mutable std::vector<double> bendingProduct_;
};

} // namespace capsula::elasticity
