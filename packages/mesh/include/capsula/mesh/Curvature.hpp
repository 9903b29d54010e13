#pragma once
// Mean and Gaussian curvature and the unit normal at every node, by three methods:
//
//   ElementAverage  the thesis's way (Sections 3.5.2, 5.5): the curvature of each
//                   incident element's quadratic map at the node, averaged with the
//                   element areas as weights;
//   JetFit          CGAL's Monge_via_jet_fitting (Cazals & Pouget 2005): a polynomial
//                   height function of the given degree fitted by least squares to the
//                   node and its neighbours;
//   QuadraticFit    the iterative local fit of Zinchenko, Rother & Davis (1997): the
//                   paraboloid z = a x^2 + b xy + c y^2 in a frame whose z axis is the
//                   normal, the normal corrected from the fit until it stops moving.
//
// The fits use a node and its neighbours within `rings` rings (NodeNeighbourhood.hpp).
// docs/curvature.md compares the three on the prolate ellipsoid of thesis Fig. 5.23: at
// mesh level 3 the jet fit is 17x and the quadratic fit 7.5x more accurate than element
// averaging (the jet converges at fourth order, the other two at second).
// Sign convention (ElementCurvature.hpp): outward normal, kappa = +1/R and K = 1/R^2 on a
// sphere of radius R.
#include <capsula/mesh/SurfaceMesh.hpp>
#include <capsula/mesh/Vec3.hpp>

#include <string>
#include <vector>

namespace capsula::mesh {

/// Curvature estimates at the nodes of a mesh (index = node).
struct NodeCurvatures {
  std::vector<double> mean;     ///< kappa = (k1 + k2) / 2
  std::vector<double> gaussian; ///< K = k1 k2
  std::vector<Vec3> normal;     ///< outward unit normal
};

enum class CurvatureMethod { ElementAverage, JetFit, QuadraticFit };

/// "element average", "jet fit", "quadratic fit" (the names a deck uses).
std::string curvatureMethodName(CurvatureMethod method);
/// Inverse of curvatureMethodName; throws InputError naming the choices.
CurvatureMethod curvatureMethodFromName(const std::string& name);

/// Element averaging: kappa_node = sum_e A_e kappa_e(node) / sum_e A_e, likewise K, and
/// the area-weighted normal (identical to nodeNormals()). A_e with the N_Q-point rule.
NodeCurvatures elementAveragedCurvature(const SurfaceMesh& mesh, int numQuadraturePoints = 7);

struct JetFitOptions {
  /// Degree of the fitted height polynomial (2..4). 4 is the most accurate from mesh
  /// level 3 on (docs/curvature.md): the quartic terms of the surface are what limits
  /// the degree-2 and degree-3 fits to second order.
  int degree = 4;
  /// Neighbourhood rings; grown by one where they hold fewer points than the degree needs.
  int rings = 2;
};

/// CGAL Monge jet fitting at every node; the fitted normal is oriented along the
/// element-averaged normal (outward).
NodeCurvatures jetFitCurvature(const SurfaceMesh& mesh, const JetFitOptions& options = {});

struct QuadraticFitOptions {
  /// Neighbourhood rings: 1 is the node's immediate neighbours, as in Zinchenko et al.;
  /// grown by one where it holds fewer than six nodes.
  int rings = 1;
  /// Stop when the fitted surface's normal is within this angle (radians) of n.
  double tolerance = 1e-12;
  /// NumericalError if it has not settled by then (2-4 iterations on resolved meshes, up
  /// to 8 on an 80-element 6:1 spheroid).
  int maxIterations = 50;
};

/// Iterative local quadratic fit, starting from the element-averaged normals.
NodeCurvatures quadraticFitCurvature(const SurfaceMesh& mesh, const QuadraticFitOptions& options = {});
/// The same from given initial normals (e.g. the previous time step's, as the thesis
/// suggests); they must point outwards.
NodeCurvatures quadraticFitCurvature(const SurfaceMesh& mesh, const std::vector<Vec3>& initialNormals,
                                     const QuadraticFitOptions& options = {});

/// Dispatch with each method's default options.
NodeCurvatures nodeCurvatures(const SurfaceMesh& mesh, CurvatureMethod method);

/// |kappa_max| = max(|k1|, |k2|) at every node.
std::vector<double> maxPrincipalCurvature(const NodeCurvatures& curvature);

/// Per element, the largest of a node quantity over the element's six nodes (eq 4.3 takes
/// kappa_max of an element as the maximum over its nodes).
std::vector<double> elementMaximum(const SurfaceMesh& mesh, const std::vector<double>& nodeValues);

} // namespace capsula::mesh
