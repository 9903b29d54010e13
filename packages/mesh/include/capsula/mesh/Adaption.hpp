#pragma once
// Curvature-driven adaption (thesis Section 4.7, eq 4.3): an element is refined where
//     Q_e = kappa_max,e^2 A_e >= threshold,
// kappa_max,e the largest principal curvature magnitude over the element's six nodes and
// A_e its area. Q is dimensionless, about the square of the angle the element's normal
// turns through, so the threshold does not depend on the cell's size. The thesis used 0.2.
#include <capsula/mesh/Curvature.hpp>
#include <capsula/mesh/Refinement.hpp>
#include <capsula/mesh/SurfaceMesh.hpp>

#include <vector>

namespace capsula::mesh {

/// Q_e of eq 4.3 for every element; areas with the N_Q-point rule.
std::vector<double> adaptionQuality(const SurfaceMesh& mesh, const NodeCurvatures& curvature,
                                    int numQuadraturePoints = 7);

/// The indices of the values >= threshold.
std::vector<int> indicesAtOrAbove(const std::vector<double>& values, double threshold);

struct AdaptionOptions {
  double threshold = 0.2; ///< eq 4.3
  CurvatureMethod curvature = CurvatureMethod::QuadraticFit;
  int numQuadraturePoints = 7; ///< for the element areas
};

/// One adaption pass: curvature by options.curvature, Q_e, and refineElements() of the
/// elements with Q_e >= threshold, carrying `fields` (e.g. the reference positions) along.
/// Nothing is refined (the mesh is returned as is, each element its own parent) if no
/// element reaches the threshold.
RefinedMesh adaptToCurvature(const SurfaceMesh& mesh, const std::vector<std::vector<double>>& fields = {},
                             const AdaptionOptions& options = {});

/// A Lagrangian membrane mesh refined where the current shape needs it.
struct AdaptedMembraneMesh {
  SurfaceMesh current;           ///< the refined topology at the current positions
  std::vector<double> reference; ///< the same nodes in the reference configuration
  int markedElements = 0;        ///< elements with Q_e >= threshold (0: nothing refined)
};

/// adaptToCurvature for a membrane: Q_e (eq 4.3) from the CURRENT shape `current`, the
/// refinement parametrised by `reference` (3 per node) with the current positions carried
/// as a field, so that every new node is one material point in both configurations and
/// sits where the membrane's own element maps (reference shape parameters) put it. Nothing
/// is refined if no element reaches the threshold, or if the refined mesh would have more
/// than `maxElements` elements (the growth stops there; `markedElements` is then 0).
AdaptedMembraneMesh adaptMembraneMesh(const SurfaceMesh& current, const std::vector<double>& reference,
                                      const AdaptionOptions& options, int maxElements);

} // namespace capsula::mesh
