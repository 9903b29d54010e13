// The iterative local quadratic fit of Zinchenko, Rother & Davis (1997), thesis Section 5.5.
//
// In a frame (t1, t2, n) at node O, with n the current normal estimate, the neighbours'
// offsets (x, y, z) are fitted by least squares with
//     z = d x + e y + a x^2 + b xy + c y^2
// (through O, since O is itself a surface point). The linear terms measure how far n is
// tilted from the fitted surface's normal, (-d, -e, 1)/|.|, which becomes the next n.
// At convergence d = e = 0: the fit is the paraboloid z = a x^2 + b xy + c y^2 about the
// normal, and kappa = -(a + c), K = 4ac - b^2 (outward n, ElementCurvature.hpp).
// Its accuracy is limited by the quartic terms of the surface, which the paraboloid
// misses: second order, with a constant that grows with the square of the neighbourhood
// radius, hence the default of one ring.
#include <capsula/mesh/Curvature.hpp>

#include <capsula/core/Error.hpp>
#include <capsula/mesh/ElementCurvature.hpp>
#include <capsula/mesh/NodeNeighbourhood.hpp>
#include <capsula/mesh/NodeNormals.hpp>

#include <Eigen/Cholesky>

#include <cmath>

namespace capsula::mesh {

namespace {

using Vec5 = Eigen::Matrix<double, 5, 1>;
using Mat5 = Eigen::Matrix<double, 5, 5>;

constexpr std::size_t minimumNeighbours = 6;

/// Unit tangents (t1, t2) with (t1, t2, n) right-handed and orthonormal.
void tangentFrame(const Vec3& n, Vec3& t1, Vec3& t2)
{
  // Cross with the coordinate axis least aligned with n: never nearly parallel.
  Vec3 axis = Vec3::Zero();
  Eigen::Index k;
  n.cwiseAbs().minCoeff(&k);
  axis[k] = 1.0;
  t1 = axis.cross(n).normalized();
  t2 = n.cross(t1);
}

/// Least-squares coefficients (d, e, a, b, c) of the height function in the frame of n,
/// from the neighbours' offsets from the node. The offsets are divided by the
/// neighbourhood radius so that the normal equations are well conditioned: the
/// coefficients are those of the scaled coordinates.
Vec5 fitHeight(const Vec3& n, const std::vector<Vec3>& offsets, double radius, Vec3& t1, Vec3& t2)
{
  tangentFrame(n, t1, t2);
  Mat5 normalMatrix = Mat5::Zero();
  Vec5 rhs = Vec5::Zero();
  for (const Vec3& d : offsets) {
    const double u = d.dot(t1) / radius, v = d.dot(t2) / radius, w = d.dot(n) / radius;
    Vec5 row;
    row << u, v, u * u, u * v, v * v;
    normalMatrix.selfadjointView<Eigen::Lower>().rankUpdate(row);
    rhs += w * row;
  }
  return normalMatrix.selfadjointView<Eigen::Lower>().ldlt().solve(rhs);
}

} // namespace

NodeCurvatures quadraticFitCurvature(const SurfaceMesh& mesh, const std::vector<Vec3>& initialNormals,
                                     const QuadraticFitOptions& options)
{
  core::require<core::InputError>(static_cast<int>(initialNormals.size()) == mesh.numNodes(),
                                  "quadraticFitCurvature: got ", initialNormals.size(), " initial normals for ",
                                  mesh.numNodes(), " nodes");
  core::require<core::InputError>(options.rings >= 1, "quadraticFitCurvature: rings = ", options.rings,
                                  " must be at least 1");
  const auto numNodes = static_cast<std::size_t>(mesh.numNodes());
  const NodeGraph graph = nodeGraph(mesh);
  std::vector<int> scratch(numNodes, -1);
  std::vector<Vec3> offsets;

  NodeCurvatures result{std::vector<double>(numNodes), std::vector<double>(numNodes), std::vector<Vec3>(numNodes)};
  for (int node = 0; node < mesh.numNodes(); ++node) {
    const auto i = static_cast<std::size_t>(node);
    const Vec3 x0 = mesh.position(node);
    // Five unknowns: take one ring more where the rings asked for hold fewer than six
    // neighbours (valence-4 vertices of a refined mesh), so the fit stays overdetermined.
    std::vector<int> neighbours = nodeNeighbourhood(graph, node, options.rings, scratch);
    for (int rings = options.rings + 1; neighbours.size() < minimumNeighbours; ++rings) {
      const std::size_t before = neighbours.size();
      neighbours = nodeNeighbourhood(graph, node, rings, scratch);
      core::require<core::InputError>(neighbours.size() > before, "quadraticFitCurvature: the mesh has ",
                                      mesh.numNodes(), " nodes, too few for a local fit");
    }
    offsets.clear();
    double radius = 0.0;
    for (int neighbour : neighbours) {
      offsets.push_back(mesh.position(neighbour) - x0);
      radius = std::max(radius, offsets.back().norm());
    }
    // Solve R(theta) = 0 for the tilt correction R = -(d t1 + e t2), written in the tangent
    // frame (s1, s2) of the initial normal n0, with n(theta) = (n0 + theta_1 s1 + theta_2 s2)/|.|.
    // Zinchenko's update theta += R assumes dR/dtheta = -I, which holds on resolved
    // meshes; where the neighbourhood turns through a large angle (coarse meshes, sharp
    // tips) the gain differs from 1 in each direction and the plain update overshoots and
    // oscillates. Broyden's secant update learns dR/dtheta from the iterates (exactly, in
    // two steps, while R is linear) and converges to the same fixed point.
    const Vec3 n0 = initialNormals[i].normalized();
    Vec3 s1, s2;
    tangentFrame(n0, s1, s2);
    Eigen::Vector2d theta = Eigen::Vector2d::Zero();
    Eigen::Matrix2d jacobian = -Eigen::Matrix2d::Identity();
    Vec3 n = n0, t1, t2;
    Vec5 fit = fitHeight(n, offsets, radius, t1, t2);
    const auto correctionOf = [&]() {
      const Vec3 step = -(fit[0] * t1 + fit[1] * t2);
      return Eigen::Vector2d(step.dot(s1), step.dot(s2));
    };
    Eigen::Vector2d correction = correctionOf();
    // |(d, e)| is the angle between n and the fitted normal (NaN-safe test).
    for (int iteration = 0; !(std::hypot(fit[0], fit[1]) < options.tolerance); ++iteration) {
      core::require<core::NumericalError>(iteration < options.maxIterations,
                                          "quadraticFitCurvature: the normal at node ", node, " did not settle within ",
                                          options.maxIterations, " iterations (tolerance ", options.tolerance,
                                          "); the node's neighbourhood may be folded or degenerate");
      const Eigen::Vector2d delta = -jacobian.inverse() * correction;
      theta += delta;
      n = (n0 + theta[0] * s1 + theta[1] * s2).normalized();
      fit = fitHeight(n, offsets, radius, t1, t2);
      const Eigen::Vector2d next = correctionOf();
      jacobian += (next - correction - jacobian * delta) * delta.transpose() / delta.squaredNorm();
      correction = next;
    }
    // Height f(x, y) in unscaled coordinates: f_x = d, f_y = e (now < tolerance),
    // f_xx = 2a/radius, f_xy = b/radius, f_yy = 2c/radius for the scaled coefficients.
    const CurvaturePair k =
        graphCurvature(fit[0], fit[1], 2.0 * fit[2] / radius, fit[3] / radius, 2.0 * fit[4] / radius);
    result.mean[i] = k.mean;
    result.gaussian[i] = k.gaussian;
    result.normal[i] = (n - fit[0] * t1 - fit[1] * t2).normalized();
  }
  return result;
}

NodeCurvatures quadraticFitCurvature(const SurfaceMesh& mesh, const QuadraticFitOptions& options)
{
  return quadraticFitCurvature(mesh, nodeNormals(mesh), options);
}

} // namespace capsula::mesh
