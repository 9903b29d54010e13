#include <capsula/mesh/Adaption.hpp>

#include <capsula/mesh/Measures.hpp>

#include <capsula/core/Error.hpp>

namespace capsula::mesh {

std::vector<double> adaptionQuality(const SurfaceMesh& mesh, const NodeCurvatures& curvature, int numQuadraturePoints)
{
  const std::vector<double> kappaMax = elementMaximum(mesh, maxPrincipalCurvature(curvature));
  std::vector<double> quality = elementAreas(mesh, numQuadraturePoints);
  for (std::size_t e = 0; e < quality.size(); ++e) {
    quality[e] *= kappaMax[e] * kappaMax[e];
  }
  return quality;
}

std::vector<int> indicesAtOrAbove(const std::vector<double>& values, double threshold)
{
  std::vector<int> indices;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (values[i] >= threshold) {
      indices.push_back(static_cast<int>(i));
    }
  }
  return indices;
}

RefinedMesh adaptToCurvature(const SurfaceMesh& mesh, const std::vector<std::vector<double>>& fields,
                             const AdaptionOptions& options)
{
  const NodeCurvatures curvature = nodeCurvatures(mesh, options.curvature);
  const std::vector<double> quality = adaptionQuality(mesh, curvature, options.numQuadraturePoints);
  return refineElements(mesh, indicesAtOrAbove(quality, options.threshold), fields);
}

AdaptedMembraneMesh adaptMembraneMesh(const SurfaceMesh& current, const std::vector<double>& reference,
                                      const AdaptionOptions& options, int maxElements)
{
  core::require<core::InputError>(reference.size() == current.positions().size(),
                                  "adaptMembraneMesh: ", reference.size(), " reference values for ", current.numNodes(),
                                  " nodes");
  AdaptedMembraneMesh result{current, reference, 0};
  const NodeCurvatures curvature = nodeCurvatures(current, options.curvature);
  const std::vector<int> marked =
      indicesAtOrAbove(adaptionQuality(current, curvature, options.numQuadraturePoints), options.threshold);
  if (marked.empty()) {
    return result;
  }
  SurfaceMesh referenceMesh = current;
  referenceMesh.setPositions(reference);
  RefinedMesh refined = refineElements(referenceMesh, marked, {current.positions()});
  if (refined.mesh.numElements() > maxElements) {
    return result;
  }
  result.current = SurfaceMesh(std::move(refined.fields[0]), refined.mesh.elements());
  result.reference = refined.mesh.positions();
  result.markedElements = static_cast<int>(marked.size());
  return result;
}

} // namespace capsula::mesh
