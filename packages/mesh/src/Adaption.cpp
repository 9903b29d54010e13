#include <capsula/mesh/Adaption.hpp>

#include <capsula/mesh/Measures.hpp>

namespace capsula::mesh {

std::vector<double> adaptionQuality(const SurfaceMesh& mesh, const NodeCurvatures& curvature,
                                    int numQuadraturePoints)
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

} // namespace capsula::mesh
