#include "capsula/elasticity/Prestress.hpp"

#include <capsula/contour/Contour.hpp>
#include <capsula/contour/ContourMetrics.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/mesh/Measures.hpp>

#include <cmath>

namespace capsula::elasticity {

namespace {

/// Refuses an alpha that is not finite and >= 0; `what` names it, `example` suggests one.
void requirePrestress(double prestress, const char* what, const char* example)
{
  core::require<core::InputError>(std::isfinite(prestress) && prestress >= 0.0, what, " is ", prestress,
                                  "; give alpha >= 0 (e.g. ", example, ", 0 for none)");
}

/// X = c + (x - c)/(1 + alpha) for `count` coordinates of points of `dimension` each, in
/// place, written as x - alpha/(1 + alpha) (x - c): exact at alpha = 0.
void shrinkAbout(const double* centre, int dimension, double prestress, double* positions, std::size_t count)
{
  const double pull = prestress / (1.0 + prestress);
  for (std::size_t i = 0; i < count; ++i) {
    positions[i] -= pull * (positions[i] - centre[i % static_cast<std::size_t>(dimension)]);
  }
}

} // namespace

std::vector<double> prestressedReference(const mesh::SurfaceMesh& initialShape, double prestress)
{
  requirePrestress(prestress, "the membrane prestress alpha = a/a0 - 1", "0.025 for 2.5%");
  const mesh::Vec3 c = mesh::centroid(initialShape);
  std::vector<double> reference(initialShape.positions());
  shrinkAbout(c.data(), 3, prestress, reference.data(), reference.size());
  return reference;
}

Eigen::Matrix2Xd prestressedReference(const Eigen::Matrix2Xd& initial, double prestress)
{
  requirePrestress(prestress, "the 2D membrane prestress alpha (initial stretch 1 + alpha)", "0.2 for 20%");
  const Eigen::Vector2d c = contour::centroid(contour::Contour(initial));
  Eigen::Matrix2Xd reference = initial;
  shrinkAbout(c.data(), 2, prestress, reference.data(), static_cast<std::size_t>(reference.size()));
  return reference;
}

} // namespace capsula::elasticity
