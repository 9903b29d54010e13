#pragma once
// Linearly implicit (Rosenbrock-W) methods for stiff systems dy/dt = f(t, y), in the
// form of Hairer & Wanner (Solving ODEs II, IV.7, eqs 7.25-7.26) that needs one matrix
// W = I - h gamma J~ per step and no products with it:
//
//   (I - h gamma J~) u_i = h gamma f(t + alpha_i h, y + sum_{j<i} a_ij u_j) + gamma sum_{j<i} c_ij u_j
//   y_new = y + sum_i m_i u_i,      error estimate e = sum_i (m_i - mEmbedded_i) u_i.
//
// J~ only approximates df/dy: a W-method keeps its order for ANY J~ (its order
// conditions do not assume J~ = df/dy), and its stability on the stiff modes needs J~ to
// be right only there. That suits a boundary-integral velocity whose exact Jacobian
// (the derivative of the layer potentials with respect to the geometry) is out of reach,
// while the stiff part (the flow operator applied to the membrane's tangent stiffness)
// is not.
//
// The methods are defined by their published coefficients in the standard form
//   (I - h gamma J~) k_i = h f(y + sum_{j<i} alpha_ij k_j) + h J~ sum_{j<i} gamma_ij k_j,
//   y_new = y + sum_i b_i k_i,
// and converted with Gamma = (gamma_ij) (gamma on the diagonal): a = alpha Gamma^-1,
// c = diag(1/gamma) - Gamma^-1, m = b Gamma^-1 (Hairer & Wanner IV.7.25).
#include <string>
#include <vector>

namespace capsula::timeint {

struct RosenbrockTableau {
  std::string name;
  int stages = 0;
  double gamma = 0.0; ///< diagonal of Gamma
  // Standard form (row-major stages x stages, zero on and above the diagonal).
  std::vector<double> alpha;            ///< alpha_ij
  std::vector<double> gammaOffDiagonal; ///< gamma_ij, i > j
  std::vector<double> b;                ///< weights of the solution that advances
  std::vector<double> bEmbedded;        ///< weights of the embedded solution
  int order = 0;                        ///< as a W-method: for any J~
  int embeddedOrder = 0;
  // Transformed form, what the integrator uses (computed by the constructors below).
  std::vector<double> a;         ///< a_ij = (alpha Gamma^-1)_ij
  std::vector<double> c;         ///< c_ij = (diag(1/gamma) - Gamma^-1)_ij
  std::vector<double> m;         ///< m = b Gamma^-1
  std::vector<double> mEmbedded; ///< mEmbedded = bEmbedded Gamma^-1
  std::vector<double> stageTime; ///< alpha_i = sum_j alpha_ij

  double aCoefficient(int i, int j) const { return a[static_cast<std::size_t>(i * stages + j)]; }
  double cCoefficient(int i, int j) const { return c[static_cast<std::size_t>(i * stages + j)]; }
  /// Order of the error estimate's leading term: min(order, embeddedOrder) + 1.
  int errorEstimateOrder() const;
};

/// Fills a, c, m, mEmbedded and stageTime from the standard-form coefficients.
void transformRosenbrockTableau(RosenbrockTableau& tableau);

/// The stability function of the solution that advances, with J~ = df/dy:
/// R(z) = 1 + z b^T (I - z (alpha + Gamma))^-1 1. L-stable methods have R(-inf) = 0.
double rosenbrockStabilityFunction(const RosenbrockTableau& tableau, double z);

/// ROS34PW2 (Rang & Angermann 2005, BIT 45): 4 stages, order 3 as a W-method with an
/// embedded order-2 solution, L-stable (R(-inf) = 0) and stiffly accurate (the solution
/// that advances is the last stage's), gamma = 0.4358665215.
RosenbrockTableau ros34pw2();

/// ROS2 (Verwer, Spee, Blom & Hundsdorfer 1999, SIAM J. Sci. Comput. 20): 2 stages,
/// order 2 as a W-method, L-stable, gamma = 1 + 1/sqrt(2); the linearly implicit Euler
/// solution of its first stage (order 1) estimates the error.
RosenbrockTableau ros2();

} // namespace capsula::timeint
