#include <capsula/mesh/Curvature.hpp>

#include <capsula/core/Error.hpp>
#include <capsula/mesh/ElementCurvature.hpp>

#include <algorithm>
#include <limits>

namespace capsula::mesh {

std::string curvatureMethodName(CurvatureMethod method)
{
  switch (method) {
  case CurvatureMethod::ElementAverage:
    return "element average";
  case CurvatureMethod::JetFit:
    return "jet fit";
  case CurvatureMethod::QuadraticFit:
    return "quadratic fit";
  }
  return "";
}

CurvatureMethod curvatureMethodFromName(const std::string& name)
{
  for (CurvatureMethod m : {CurvatureMethod::ElementAverage, CurvatureMethod::JetFit, CurvatureMethod::QuadraticFit}) {
    if (name == curvatureMethodName(m)) {
      return m;
    }
  }
  throw core::InputError(core::message("Unknown curvature method \"", name,
                                       "\"; use \"element average\", \"jet fit\" or \"quadratic fit\""));
}

NodeCurvatures nodeCurvatures(const SurfaceMesh& mesh, CurvatureMethod method)
{
  switch (method) {
  case CurvatureMethod::ElementAverage:
    return elementAveragedCurvature(mesh);
  case CurvatureMethod::JetFit:
    return jetFitCurvature(mesh);
  case CurvatureMethod::QuadraticFit:
    return quadraticFitCurvature(mesh);
  }
  return elementAveragedCurvature(mesh);
}

std::vector<double> maxPrincipalCurvature(const NodeCurvatures& curvature)
{
  std::vector<double> kappaMax(curvature.mean.size());
  for (std::size_t i = 0; i < kappaMax.size(); ++i) {
    kappaMax[i] = maxAbsPrincipalCurvature(curvature.mean[i], curvature.gaussian[i]);
  }
  return kappaMax;
}

std::vector<double> elementMaximum(const SurfaceMesh& mesh, const std::vector<double>& nodeValues)
{
  core::require<core::InputError>(static_cast<int>(nodeValues.size()) == mesh.numNodes(), "elementMaximum: got ",
                                  nodeValues.size(), " node values for ", mesh.numNodes(), " nodes");
  std::vector<double> result(static_cast<std::size_t>(mesh.numElements()), -std::numeric_limits<double>::infinity());
  for (int e = 0; e < mesh.numElements(); ++e) {
    for (int node : mesh.element(e)) {
      result[static_cast<std::size_t>(e)] =
          std::max(result[static_cast<std::size_t>(e)], nodeValues[static_cast<std::size_t>(node)]);
    }
  }
  return result;
}

} // namespace capsula::mesh
