#pragma once
// Membrane force transmitted across one curved element edge: the building block of
// the element-averaged load (thesis eq 3.37 with the ERRATA reading)
//     <Delta f>_m = -(1/A_m) oint_{C_m} T . b dl,
// b the in-surface unit normal to the contour C_m pointing out of element m.
//
// Choices (the thesis interpolates T "linearly from the nodal values"):
//  - the edge is the quadratic curve through its three nodes, the midside node at the
//    parameter tau_m of eq 3.17 (the element map restricted to the edge);
//  - T and the unit normal are interpolated QUADRATICALLY from the three nodes along
//    it (the edge's own shape functions); T is projected onto the tangent plane of the
//    interpolated normal, so the force it transmits stays in the surface (eq 3.26);
//  - b = x' x n / |x' x n|, with the interpolated nodal normal n, which both elements
//    sharing the edge see alike: integrated once and added with opposite signs to the
//    two elements, so the forces cancel exactly in the sum over a closed membrane;
//  - Gauss-Legendre in the edge parameter (the integrand is smooth but not polynomial).
#include "capsula/elasticity/SurfaceKinematics.hpp"

#include <capsula/quadrature/Rule1D.hpp>

#include <array>
#include <cstddef>

namespace capsula::elasticity {

/// Nodal data along one edge, in traversal order: start vertex, midside node, end vertex.
struct EdgeNodalData {
  std::array<Vec3, 3> position;
  std::array<Vec3, 3> normal;  ///< unit nodal normals
  std::array<Mat3, 3> tension; ///< nodal tension tensors
};

/// Parameter of the midside node along the edge, tau_m = |x_m - x_s| / (|x_m - x_s| +
/// |x_m - x_e|): the alpha, beta or gamma of eq 3.17 seen from the start vertex.
inline double edgeMidParameter(const Vec3& start, const Vec3& mid, const Vec3& end)
{
  const double toStart = (mid - start).norm();
  return toStart / (toStart + (mid - end).norm());
}

/// Quadratic Lagrange basis on the nodes {0, tau_m, 1} and its derivative at t.
inline void edgeShapeFunctions(double midParameter, double t, double L[3], double dL[3])
{
  const double m = midParameter;
  L[0] = (t - m) * (t - 1.0) / m;
  L[1] = t * (t - 1.0) / (m * (m - 1.0));
  L[2] = t * (t - m) / (1.0 - m);
  dL[0] = (2.0 * t - m - 1.0) / m;
  dL[1] = (2.0 * t - 1.0) / (m * (m - 1.0));
  dL[2] = (2.0 * t - m) / (1.0 - m);
}

/// What an edge transmits: F = int_edge T . b dl and its moment M = int_edge x x (T . b) dl.
struct EdgeResultant {
  Vec3 force = Vec3::Zero();
  Vec3 moment = Vec3::Zero();
};

/// int_edge T . b dl (and its moment about the origin) with b = x' x n / |x' x n|: to the
/// right of the direction of travel seen from the side n points to, i.e. out of the
/// element whose boundary runs counter-clockwise (seen from outside) in this direction.
/// `rule` is on [0, 1].
inline EdgeResultant edgeTensionResultant(const EdgeNodalData& edge, double midParameter,
                                          const quadrature::Rule1D& rule)
{
  EdgeResultant resultant;
  double L[3], dL[3];
  for (std::size_t q = 0; q < rule.points.size(); ++q) {
    edgeShapeFunctions(midParameter, rule.points[q], L, dL);
    Vec3 position = Vec3::Zero(), tangent = Vec3::Zero(), normal = Vec3::Zero();
    Mat3 tension = Mat3::Zero();
    for (int i = 0; i < 3; ++i) {
      position += L[i] * edge.position[i];
      tangent += dL[i] * edge.position[i];
      normal += L[i] * edge.normal[i];
      tension += L[i] * edge.tension[i];
    }
    normal.normalize();
    const Vec3 outward = tangent.cross(normal); // |outward| = |x'| sin(x', n)
    // b dl = outward / |outward| * |x'| dt; P T P b = P (T b) because b is tangent.
    const Vec3 traction = tension * outward;
    const Vec3 inPlane = traction - normal.dot(traction) * normal;
    const Vec3 contribution = (rule.weights[q] * tangent.norm() / outward.norm()) * inPlane;
    resultant.force += contribution;
    resultant.moment += position.cross(contribution);
  }
  return resultant;
}

/// int_edge T . b dl alone (see edgeTensionResultant).
inline Vec3 edgeTensionForce(const EdgeNodalData& edge, double midParameter, const quadrature::Rule1D& rule)
{
  return edgeTensionResultant(edge, midParameter, rule).force;
}

} // namespace capsula::elasticity
