#include <capsula/mesh/EquivalentEllipsoid.hpp>

#include <capsula/core/Error.hpp>
#include <capsula/mesh/Measures.hpp>
#include <capsula/mesh/SurfaceIntegral.hpp>
#include <capsula/quadrature/TriangleRule.hpp>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace capsula::mesh {

namespace {

/// M = int_V (x - c)(x - c)^T dV by the divergence theorem.
Mat3 secondMoment(const SurfaceMesh& mesh, const Vec3& c, int numQuadraturePoints)
{
  return integrateOverSurface(
      mesh, quadrature::triangleRule(numQuadraturePoints),
      [&c](const SurfacePoint& s) -> Mat3 {
        const Vec3 y = s.position - c;
        return (y.dot(s.normal) / 5.0) * (y * y.transpose());
      },
      Mat3(Mat3::Zero()));
}

} // namespace

Mat3 inertiaTensor(const SurfaceMesh& mesh, int numQuadraturePoints)
{
  const Mat3 m = secondMoment(mesh, centroid(mesh, numQuadraturePoints), numQuadraturePoints);
  return m.trace() * Mat3::Identity() - m;
}

EquivalentEllipsoid equivalentEllipsoid(const SurfaceMesh& mesh, int numQuadraturePoints)
{
  EquivalentEllipsoid result;
  result.volume = enclosedVolume(mesh, numQuadraturePoints);
  core::require<core::NumericalError>(result.volume > 0.0, "equivalentEllipsoid: the enclosed volume is ",
                                      result.volume, "; the surface is inverted or degenerate");
  result.centre = centroid(mesh, numQuadraturePoints);
  const Eigen::SelfAdjointEigenSolver<Mat3> eigen(secondMoment(mesh, result.centre, numQuadraturePoints));
  core::require<core::NumericalError>(eigen.info() == Eigen::Success,
                                      "equivalentEllipsoid: the eigen-decomposition of the second moment failed");
  // Eigen sorts eigenvalues ascending; the semi-axes are wanted descending.
  for (int i = 0; i < 3; ++i) {
    const double mu = eigen.eigenvalues()[2 - i];
    result.semiAxes[i] = std::sqrt(5.0 * std::max(mu, 0.0) / result.volume);
    result.axes.col(i) = eigen.eigenvectors().col(2 - i);
  }
  if (result.axes.determinant() < 0.0) {
    result.axes.col(2) *= -1.0;
  }
  return result;
}

} // namespace capsula::mesh
