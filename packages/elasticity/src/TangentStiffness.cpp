#include "capsula/elasticity/TangentStiffness.hpp"

#include <capsula/core/Error.hpp>

#include <algorithm>

namespace capsula::elasticity {

TangentStiffness::TangentStiffness(const mesh::SurfaceMesh& mesh, std::vector<ElementStiffness> elements,
                                   std::shared_ptr<HelfrichBending> bending)
    : mesh_(&mesh), elements_(std::move(elements)), bending_(std::move(bending))
{
  core::require(elements_.size() == static_cast<std::size_t>(mesh.numElements()),
                "TangentStiffness: ", elements_.size(), " element matrices for ", mesh.numElements(), " elements");
}

void TangentStiffness::apply(const double* x, double* y) const
{
  std::fill(y, y + 3 * static_cast<std::size_t>(numNodes()), 0.0);
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    const auto& nodes = mesh_->element(static_cast<int>(e));
    double local[18], result[18];
    for (int k = 0; k < 6; ++k) {
      for (int i = 0; i < 3; ++i) {
        local[3 * k + i] = x[3 * nodes[static_cast<std::size_t>(k)] + i];
      }
    }
    const ElementStiffness& K = elements_[e];
    for (int r = 0; r < 18; ++r) {
      double sum = 0.0;
      for (int c = 0; c < 18; ++c) {
        sum += K[static_cast<std::size_t>(r * 18 + c)] * local[c];
      }
      result[r] = sum;
    }
    for (int k = 0; k < 6; ++k) {
      for (int i = 0; i < 3; ++i) {
        y[3 * nodes[static_cast<std::size_t>(k)] + i] += result[3 * k + i];
      }
    }
  }
  if (bending_) {
    bendingProduct_.resize(3 * static_cast<std::size_t>(numNodes()));
    bending_->applyStiffness(x, bendingProduct_.data());
    for (std::size_t i = 0; i < bendingProduct_.size(); ++i) {
      y[i] += bendingProduct_[i];
    }
  }
}

} // namespace capsula::elasticity
