#include "capsula/elasticity/HelfrichBending.hpp"

#include "capsula/elasticity/BendingIntegrand.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/quadrature/TriangleRule.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace capsula::elasticity {

namespace {

// The rule of the energy, the Lagrangian and K; SurfaceMassMatrix integrates M with the
// same rule, which the exact gradient needs (the Lagrangian differentiates that M).
constexpr int numPoints = 7;

std::size_t at(int index)
{
  return static_cast<std::size_t>(index);
}

// Tangents a_1 = sum_k d_xi phi_k x_k, a_2 = sum_k d_eta phi_k x_k.
std::array<Vec3, 2> tangents(const mesh::ElementNodes& x, const double* dXi, const double* dEta)
{
  std::array<Vec3, 2> a = {Vec3::Zero(), Vec3::Zero()};
  for (int k = 0; k < 6; ++k) {
    a[0] += dXi[k] * x[at(k)];
    a[1] += dEta[k] * x[at(k)];
  }
  return a;
}

} // namespace

HelfrichBending::HelfrichBending(const mesh::SurfaceMesh& mesh, std::vector<double> referencePositions,
                                 const BendingParameters& parameters)
    : mesh_(&mesh), reference_(std::move(referencePositions)), parameters_(parameters), mass_(mesh)
{
  const double kb = parameters.modulus, c0 = parameters.spontaneousCurvature;
  core::require<core::InputError>(std::isfinite(kb) && kb >= 0.0,
                                  "'Bending modulus' must be a finite number >= 0, got ", kb);
  core::require<core::InputError>(std::isfinite(c0), "'Spontaneous curvature' must be finite, got ", c0);
  core::require<core::InputError>(c0 == 0.0 || kb > 0.0, "'Spontaneous curvature' = ", c0,
                                  " has no effect with 'Bending modulus' = 0: set it to 0 or give a positive modulus");
  core::require<core::InputError>(
      c0 == 0.0 || parameters.reference == BendingReference::Flat, "'Spontaneous curvature' must be 0 with ",
      "'Bending reference' = 'Initial shape' (the reference's own curvature is the spontaneous curvature), got ", c0);
  const int numNodes = mesh.numNodes(), numElements = mesh.numElements();
  core::require<core::InputError>(reference_.size() == 3 * at(numNodes), "the 'Bending reference' shape has ",
                                  reference_.size(), " coordinates but the mesh has ", numNodes, " nodes (",
                                  3 * numNodes, " coordinates expected)");

  // Reference shape parameters, and the shape functions at the quadrature points and
  // nodes with them: fixed from here on, so that the element maps are linear in x.
  const quadrature::TriangleRule& rule = quadrature::triangleRule(numPoints);
  referenceParameters_.resize(at(numElements));
  points_.resize(at(numElements) * numPoints);
  nodeDerivative_.resize(6 * at(numElements));
  for (int e = 0; e < numElements; ++e) {
    const mesh::ElementNodes X = mesh.elementNodes(e, reference_.data());
    const mesh::ShapeParameters p = mesh::shapeParameters(X);
    referenceParameters_[at(e)] = p;
    for (int q = 0; q < numPoints; ++q) {
      QuadraturePoint& point = points_[at(e) * numPoints + at(q)];
      point.weight = rule.weight[at(q)];
      mesh::shapeFunctions(p, rule.xi[at(q)], rule.eta[at(q)], point.phi);
      mesh::shapeFunctionDerivatives(p, rule.xi[at(q)], rule.eta[at(q)], point.dXi, point.dEta);
      const auto a = tangents(X, point.dXi, point.dEta);
      const double J = a[0].cross(a[1]).norm();
      core::require<core::InputError>(std::isfinite(J) && J > 0.0, "the 'Bending reference' shape is degenerate in ",
                                      "element ", e, " (area element ", J, " at a quadrature point)");
    }
    for (int j = 0; j < 6; ++j) {
      const auto c = mesh::nodeParametricCoordinates(p, j);
      std::array<double, 12>& d = nodeDerivative_[6 * at(e) + at(j)];
      mesh::shapeFunctionDerivatives(p, c[0], c[1], d.data(), d.data() + 6);
    }
  }
  buildPattern();

  stiffness_.assign(column_.size(), 0.0);
  massValues_.assign(column_.size(), 0.0);
  massBound_.assign(at(numNodes), 0.0);
  elementArea_.assign(at(numElements), 0.0);
  for (auto* v : {&rhs_, &spontaneousForce_, &work_, &solution_}) {
    v->assign(3 * at(numNodes), 0.0);
  }
  multiplier_.assign(at(numNodes), Vec3::Zero());
  spontaneousSolution_.assign(at(numNodes), Vec3::Zero());
  curvature_.assign(at(numNodes), Vec3::Zero());
  meanCurvature_.assign(at(numNodes), 0.0);
  normal_.assign(at(numNodes), Vec3::Zero());
  force_.assign(at(numNodes), Vec3::Zero());

  spontaneous_.assign(at(numNodes), c0);
  for (QuadraturePoint& point : points_) {
    point.c = c0;
  }
  if (parameters.reference == BendingReference::InitialShape) {
    setReferenceCurvature();
  }
  hasSpontaneous_ = std::any_of(points_.begin(), points_.end(), [](const QuadraturePoint& point) {
    return point.c != 0.0 || point.beta[0] != 0.0 || point.beta[1] != 0.0;
  });
}

void HelfrichBending::setReferenceCurvature()
{
  // R = Y_h of the reference at every quadrature point, in the element's frame there.
  try {
    solveCurvature(reference_.data());
  } catch (const core::NumericalError& error) {
    throw core::InputError(core::message("the curvature of the 'Bending reference' shape cannot be computed (",
                                         error.what(), "): 'Initial shape' needs a non-degenerate reference"));
  }
  const mesh::SurfaceMesh& mesh = *mesh_;
  for (int k = 0; k < mesh.numNodes(); ++k) {
    spontaneous_[at(k)] = 2.0 * meanCurvature_[at(k)];
    core::require<core::InputError>(std::isfinite(spontaneous_[at(k)]), "the curvature of the 'Bending reference' ",
                                    "shape is not finite at node ", k);
  }
  for (int e = 0; e < mesh.numElements(); ++e) {
    const mesh::ElementNodes X = mesh.elementNodes(e, reference_.data());
    const auto& nodes = mesh.element(e);
    for (int q = 0; q < numPoints; ++q) {
      QuadraturePoint& point = points_[at(e) * numPoints + at(q)];
      const auto a = tangents(X, point.dXi, point.dEta);
      const TangentFrame f = tangentFrame(a[0], a[1]);
      Vec3 Y = Vec3::Zero();
      for (int k = 0; k < 6; ++k) {
        Y += point.phi[k] * curvature_[at(nodes[at(k)])];
      }
      point.c = Y.dot(f.normal);
      point.beta[0] = Y.dot(f.dual[0]);
      point.beta[1] = Y.dot(f.dual[1]);
    }
  }
}

void HelfrichBending::buildPattern()
{
  // Node k couples to every node of every element that holds k.
  const mesh::SurfaceMesh& mesh = *mesh_;
  std::vector<std::vector<int>> neighbours(at(mesh.numNodes()));
  for (int e = 0; e < mesh.numElements(); ++e) {
    for (const int k : mesh.element(e)) {
      for (const int l : mesh.element(e)) {
        neighbours[at(k)].push_back(l);
      }
    }
  }
  rowStart_.assign(1, 0);
  column_.clear();
  for (auto& row : neighbours) {
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    column_.insert(column_.end(), row.begin(), row.end());
    rowStart_.push_back(static_cast<int>(column_.size()));
  }
  entry_.resize(at(mesh.numElements()));
  for (int e = 0; e < mesh.numElements(); ++e) {
    for (int k = 0; k < 6; ++k) {
      const int row = mesh.element(e)[at(k)];
      const auto first = column_.begin() + rowStart_[at(row)], last = column_.begin() + rowStart_[at(row) + 1];
      for (int l = 0; l < 6; ++l) {
        entry_[at(e)][at(6 * k + l)] =
            static_cast<int>(std::lower_bound(first, last, mesh.element(e)[at(l)]) - column_.begin());
      }
    }
  }
}

void HelfrichBending::assembleOperators(const double* positions)
{
  // M (in mass_, reference shape parameters), K and the area-weighted nodal normals.
  const mesh::SurfaceMesh& mesh = *mesh_;
  mass_.assemble(positions, referenceParameters_);
  std::fill(stiffness_.begin(), stiffness_.end(), 0.0);
  std::fill(massValues_.begin(), massValues_.end(), 0.0);
  for (Vec3& n : normal_) {
    n.setZero();
  }
  for (int e = 0; e < mesh.numElements(); ++e) {
    const mesh::ElementNodes x = mesh.elementNodes(e, positions);
    double K[36] = {};
    double area = 0.0;
    for (int q = 0; q < numPoints; ++q) {
      const QuadraturePoint& point = points_[at(e) * numPoints + at(q)];
      const auto a = tangents(x, point.dXi, point.dEta);
      const TangentFrame f = tangentFrame(a[0], a[1]);
      core::require<core::NumericalError>(std::isfinite(f.J) && f.J > 0.0, "the bending energy meets a degenerate ",
                                          "element ", e, " (area element ", f.J, ")");
      const double w = point.weight * f.J;
      area += w;
      // K_kl += w g^ij d_i phi_k d_j phi_l
      for (int k = 0; k < 6; ++k) {
        const double s1 = w * (f.inverse[0][0] * point.dXi[k] + f.inverse[0][1] * point.dEta[k]);
        const double s2 = w * (f.inverse[1][0] * point.dXi[k] + f.inverse[1][1] * point.dEta[k]);
        for (int l = 0; l < 6; ++l) {
          K[6 * k + l] += s1 * point.dXi[l] + s2 * point.dEta[l];
        }
      }
    }
    elementArea_[at(e)] = area;
    const std::array<double, 36>& M = mass_.elementMatrix(e);
    for (int kl = 0; kl < 36; ++kl) {
      stiffness_[at(entry_[at(e)][at(kl)])] += K[kl];
      massValues_[at(entry_[at(e)][at(kl)])] += M[at(kl)];
    }
    for (int j = 0; j < 6; ++j) {
      const std::array<double, 12>& d = nodeDerivative_[6 * at(e) + at(j)];
      const auto a = tangents(x, d.data(), d.data() + 6);
      normal_[at(mesh.element(e)[at(j)])] += area * a[0].cross(a[1]).normalized();
    }
  }
  for (Vec3& n : normal_) {
    n.normalize();
  }
  for (std::size_t k = 0; k + 1 < rowStart_.size(); ++k) {
    double sum = 0.0;
    for (int p = rowStart_[k]; p < rowStart_[k + 1]; ++p) {
      sum += std::abs(massValues_[at(p)]);
    }
    massBound_[k] = sum;
  }
}

void HelfrichBending::applyLaplacian(const double* v, double* y) const
{
  for (std::size_t k = 0; k + 1 < rowStart_.size(); ++k) {
    double sum[3] = {0.0, 0.0, 0.0};
    for (int p = rowStart_[k]; p < rowStart_[k + 1]; ++p) {
      const double* vl = v + 3 * at(column_[at(p)]);
      const double K = stiffness_[at(p)];
      sum[0] += K * vl[0];
      sum[1] += K * vl[1];
      sum[2] += K * vl[2];
    }
    y[3 * k] = sum[0];
    y[3 * k + 1] = sum[1];
    y[3 * k + 2] = sum[2];
  }
}

void HelfrichBending::solveCurvature(const double* positions)
{
  // M Y = K x, each coordinate; H_k = Y_k . n_k / 2.
  assembleOperators(positions);
  applyLaplacian(positions, rhs_.data());
  mass_.solve(rhs_.data(), curvature_.front().data());
  for (std::size_t k = 0; k < curvature_.size(); ++k) {
    meanCurvature_[k] = 0.5 * curvature_[k].dot(normal_[k]);
  }
}

void HelfrichBending::energyAndSpontaneousTerm(const double* positions)
{
  // E = (k_b/2) int |Y_h - R|^2 dA and N_k = int phi_k R dA, R = c n_e + beta^i a_i, then
  // Lambda = -k_b (Y - M^-1 N), the multiplier that makes dL/dY = 0.
  const mesh::SurfaceMesh& mesh = *mesh_;
  const double kb = parameters_.modulus;
  energy_ = 0.0;
  std::fill(spontaneousForce_.begin(), spontaneousForce_.end(), 0.0);
  for (int e = 0; e < mesh.numElements(); ++e) {
    const mesh::ElementNodes x = mesh.elementNodes(e, positions);
    const auto& nodes = mesh.element(e);
    for (int q = 0; q < numPoints; ++q) {
      const QuadraturePoint& point = points_[at(e) * numPoints + at(q)];
      const auto a = tangents(x, point.dXi, point.dEta);
      const Vec3 area = a[0].cross(a[1]);
      const double J = area.norm();
      const Vec3 n = area / J;
      Vec3 Y = Vec3::Zero();
      for (int k = 0; k < 6; ++k) {
        Y += point.phi[k] * curvature_[at(nodes[at(k)])];
      }
      const Vec3 R = point.c * n + point.beta[0] * a[0] + point.beta[1] * a[1];
      const double w = point.weight * J;
      energy_ += 0.5 * kb * w * (Y - R).squaredNorm();
      for (int k = 0; hasSpontaneous_ && k < 6; ++k) {
        double* N = spontaneousForce_.data() + 3 * at(nodes[at(k)]);
        for (int d = 0; d < 3; ++d) {
          N[d] += w * point.phi[k] * R[d];
        }
      }
    }
  }
  if (hasSpontaneous_) {
    mass_.solve(spontaneousForce_.data(), spontaneousSolution_.front().data());
  }
  for (std::size_t k = 0; k < multiplier_.size(); ++k) {
    multiplier_[k] = -kb * (curvature_[k] - (hasSpontaneous_ ? spontaneousSolution_[k] : Vec3::Zero()));
  }
}

void HelfrichBending::addForces(const double* positions)
{
  // dE/dx_k = dL/dx_k at fixed Y and Lambda (BendingIntegrand.hpp), element by element.
  const mesh::SurfaceMesh& mesh = *mesh_;
  for (Vec3& F : force_) {
    F.setZero();
  }
  BendingPointFields fields;
  fields.modulus = parameters_.modulus;
  for (int e = 0; e < mesh.numElements(); ++e) {
    const mesh::ElementNodes x = mesh.elementNodes(e, positions);
    const auto& nodes = mesh.element(e);
    Vec3 gradient[6];
    for (Vec3& g : gradient) {
      g.setZero();
    }
    for (int q = 0; q < numPoints; ++q) {
      const QuadraturePoint& point = points_[at(e) * numPoints + at(q)];
      const auto a = tangents(x, point.dXi, point.dEta);
      fields.Y.setZero();
      fields.lambda.setZero();
      fields.lambdaDerivative = {Vec3::Zero(), Vec3::Zero()};
      fields.c = point.c;
      fields.beta[0] = point.beta[0];
      fields.beta[1] = point.beta[1];
      for (int k = 0; k < 6; ++k) {
        const std::size_t node = at(nodes[at(k)]);
        fields.Y += point.phi[k] * curvature_[node];
        fields.lambda += point.phi[k] * multiplier_[node];
        fields.lambdaDerivative[0] += point.dXi[k] * multiplier_[node];
        fields.lambdaDerivative[1] += point.dEta[k] * multiplier_[node];
      }
      const auto d = lagrangianTangentDerivative(a[0], a[1], tangentFrame(a[0], a[1]), fields);
      for (int k = 0; k < 6; ++k) {
        gradient[k] += point.weight * (point.dXi[k] * d[0] + point.dEta[k] * d[1]);
      }
    }
    for (int k = 0; k < 6; ++k) {
      force_[at(nodes[at(k)])] += gradient[k];
    }
  }
}

void HelfrichBending::evaluate(const double* positions)
{
  solveCurvature(positions);
  energyAndSpontaneousTerm(positions);
  addForces(positions);
  evaluated_ = true;
}

void HelfrichBending::applyStiffness(const double* v, double* y)
{
  // y = k_b P K M^-1 K P v, P = n n^T per node.
  core::require(evaluated_, "HelfrichBending::applyStiffness needs a linearisation point: call evaluate() first");
  const std::size_t numNodes = normal_.size();
  for (std::size_t k = 0; k < numNodes; ++k) {
    const Vec3 vk(v[3 * k], v[3 * k + 1], v[3 * k + 2]);
    const Vec3 pv = normal_[k] * normal_[k].dot(vk);
    for (int d = 0; d < 3; ++d) {
      work_[3 * k + at(d)] = pv[d];
    }
  }
  applyLaplacian(work_.data(), rhs_.data());
  mass_.solve(rhs_.data(), solution_.data());
  applyLaplacian(solution_.data(), y);
  for (std::size_t k = 0; k < numNodes; ++k) {
    const Vec3 yk(y[3 * k], y[3 * k + 1], y[3 * k + 2]);
    const Vec3 py = parameters_.modulus * normal_[k] * normal_[k].dot(yk);
    for (int d = 0; d < 3; ++d) {
      y[3 * k + at(d)] = py[d];
    }
  }
}

} // namespace capsula::elasticity
