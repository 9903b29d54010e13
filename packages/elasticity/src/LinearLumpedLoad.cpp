#include "capsula/elasticity/LinearLumpedLoad.hpp"

#include <capsula/core/Error.hpp>

#include <algorithm>

namespace capsula::elasticity {

LinearLumpedLoad::LinearLumpedLoad(const mesh::SurfaceMesh& mesh)
    : mesh_(&mesh),
      force_(static_cast<std::size_t>(mesh.numNodes()), mesh::Vec3::Zero()),
      area_(static_cast<std::size_t>(mesh.numNodes()), 0.0)
{
  std::vector<bool> vertex(static_cast<std::size_t>(mesh.numNodes()), false);
  for (const mesh::Edge& edge : mesh.edges()) {
    vertex[static_cast<std::size_t>(edge.vertices[0])] = true;
    vertex[static_cast<std::size_t>(edge.vertices[1])] = true;
  }
  for (int k = 0; k < mesh.numNodes(); ++k) {
    if (vertex[static_cast<std::size_t>(k)]) {
      vertices_.push_back(k);
    }
  }
}

void LinearLumpedLoad::apply(const double* F, const double* areas, double* f, bool add)
{
  for (const int v : vertices_) {
    force_[static_cast<std::size_t>(v)] = mesh::nodeAt(F, v);
    area_[static_cast<std::size_t>(v)] = areas[v];
  }
  for (const mesh::Edge& edge : mesh_->edges()) {
    for (const int v : edge.vertices) {
      force_[static_cast<std::size_t>(v)] += 0.5 * mesh::nodeAt(F, edge.midNode);
      area_[static_cast<std::size_t>(v)] += 0.5 * areas[edge.midNode];
    }
  }
  const auto store = [f, add](int node, const mesh::Vec3& value) {
    for (int d = 0; d < 3; ++d) {
      double& out = f[3 * static_cast<std::size_t>(node) + static_cast<std::size_t>(d)];
      out = add ? out + value[d] : value[d];
    }
  };
  for (const int v : vertices_) {
    const double A = area_[static_cast<std::size_t>(v)];
    core::require<core::NumericalError>(A > 0.0, "the linear lumped area of node ", v, " is ", A,
                                        " (a crushed element next to it)");
    force_[static_cast<std::size_t>(v)] /= A; // f_v, kept for the midside interpolation
    store(v, force_[static_cast<std::size_t>(v)]);
  }
  for (const mesh::Edge& edge : mesh_->edges()) {
    store(edge.midNode, 0.5 * (force_[static_cast<std::size_t>(edge.vertices[0])] +
                               force_[static_cast<std::size_t>(edge.vertices[1])]));
  }
}

} // namespace capsula::elasticity
