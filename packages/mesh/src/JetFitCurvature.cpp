// Curvature by CGAL's Monge jet fitting (Cazals & Pouget 2005): in the principal frame of
// the point set, a bivariate polynomial height function of degree `degree` is fitted by
// least squares to the node and its neighbours; the Monge form at the node gives the
// normal and the principal curvatures.
#include <capsula/mesh/Curvature.hpp>

#include <capsula/core/Error.hpp>
#include <capsula/mesh/NodeNeighbourhood.hpp>
#include <capsula/mesh/NodeNormals.hpp>

#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Simple_cartesian.h>

namespace capsula::mesh {

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using MongeFitting = CGAL::Monge_via_jet_fitting<Kernel>;

} // namespace

NodeCurvatures jetFitCurvature(const SurfaceMesh& mesh, const JetFitOptions& options)
{
  core::require<core::InputError>(options.degree >= 2 && options.degree <= 4,
                                  "jetFitCurvature: degree = ", options.degree,
                                  " must be 2, 3 or 4 (curvature needs a quadratic jet)");
  core::require<core::InputError>(options.rings >= 1, "jetFitCurvature: rings = ", options.rings,
                                  " must be at least 1");
  const auto numNodes = static_cast<std::size_t>(mesh.numNodes());
  const auto needed = static_cast<std::size_t>((options.degree + 1) * (options.degree + 2) / 2);
  const std::vector<Vec3> outward = nodeNormals(mesh);
  const NodeGraph graph = nodeGraph(mesh);
  std::vector<int> scratch(numNodes, -1);
  std::vector<Kernel::Point_3> points;

  NodeCurvatures result{std::vector<double>(numNodes), std::vector<double>(numNodes), std::vector<Vec3>(numNodes)};
  MongeFitting fitting;
  for (int node = 0; node < mesh.numNodes(); ++node) {
    std::vector<int> neighbours = nodeNeighbourhood(graph, node, options.rings, scratch);
    for (int rings = options.rings + 1; neighbours.size() + 1 < needed; ++rings) {
      const std::size_t before = neighbours.size();
      neighbours = nodeNeighbourhood(graph, node, rings, scratch);
      core::require<core::InputError>(neighbours.size() > before, "jetFitCurvature: the mesh has ", mesh.numNodes(),
                                      " nodes, too few for a degree-", options.degree, " jet");
    }
    // CGAL expands the jet about the first point of the range.
    points.clear();
    const Vec3 x0 = mesh.position(node);
    points.emplace_back(x0[0], x0[1], x0[2]);
    for (int n : neighbours) {
      const Vec3 x = mesh.position(n);
      points.emplace_back(x[0], x[1], x[2]);
    }
    MongeFitting::Monge_form form = fitting(points.begin(), points.end(), static_cast<std::size_t>(options.degree), 2);
    const Vec3& n = outward[static_cast<std::size_t>(node)];
    form.comply_wrt_given_normal(Kernel::Vector_3(n[0], n[1], n[2]));
    // Monge form: z = (k1 x^2 + k2 y^2)/2 + ... with z along the (now outward) normal;
    // a sphere bends away from its outward normal, so k1 = k2 = -1/R there.
    const std::vector<double>& coefficients = form.coefficients(); // k1 >= k2 come first
    const double k1 = coefficients.at(0);
    const double k2 = coefficients.at(1);
    const auto i = static_cast<std::size_t>(node);
    result.mean[i] = -0.5 * (k1 + k2);
    result.gaussian[i] = k1 * k2;
    const Kernel::Vector_3 fitted = form.normal_direction();
    result.normal[i] = Vec3(fitted.x(), fitted.y(), fitted.z()).normalized();
  }
  return result;
}

} // namespace capsula::mesh
