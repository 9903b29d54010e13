#pragma once
// Explicit Runge-Kutta methods as Butcher tableaux:
//
//   k_i   = f(t + c_i h, y + h sum_{j<i} a_ij k_j),   i = 1..s
//   y_new = y + h sum_i b_i k_i                      (the solution that advances)
//   e     = h sum_i (b_i - bEmbedded_i) k_i          (local error estimate, embedded pairs)
//
// The thesis writes its stages as k_i = h f(...) (eq 3.47); here k_i is the slope and
// h multiplies the sums. The coefficients are the same.
#include <string>
#include <vector>

namespace capsula::timeint {

struct ButcherTableau {
  std::string name;
  int stages = 0;
  std::vector<double> a;         ///< stages x stages, row-major, zero on and above the diagonal
  std::vector<double> b;         ///< weights of the solution that advances
  std::vector<double> bEmbedded; ///< weights of the companion solution; empty: no error estimate
  std::vector<double> c;         ///< stage times, c_i = sum_j a_ij
  int order = 0;                 ///< order of the solution that advances
  int embeddedOrder = 0;         ///< order of the companion solution (0: none)
  /// "First same as last": the last stage is evaluated at (t + h, y_new), so it is the
  /// first stage of the next step (a_sj = b_j, c_s = 1, b_s = 0).
  bool firstSameAsLast = false;

  double coefficient(int i, int j) const { return a[static_cast<std::size_t>(i * stages + j)]; }
  bool hasErrorEstimate() const { return !bEmbedded.empty(); }
  /// Order of the error estimate's leading term: min(order, embeddedOrder) + 1.
  int errorEstimateOrder() const;
};

/// The stability function of the solution that advances, R(z) = 1 + z b^T (I - z A)^-1 1,
/// at a real z: a step of size h on y' = mu y multiplies y by R(h mu).
double stabilityFunction(const ButcherTableau& tableau, double z);

/// The largest r such that |R(-x)| <= 1 for every x in [0, r]: a step h is stable on a
/// decaying mode y' = -rho y while h rho <= r (RK4: 2.785; RKF45's 4th-order solution:
/// 3.02, its 5th: 3.68; Dormand-Prince: 3.31).
double realStabilityBoundary(const ButcherTableau& tableau);

/// Runge-Kutta-Fehlberg 4(5), thesis eqs 3.47-3.49 (= A.49-A.51) with the ERRATA fix
/// 2197/4104 in the 4th-order weights. The 4th-order solution advances (as in the
/// thesis); the 5th-order one only estimates the error.
ButcherTableau rungeKuttaFehlberg45();

/// RKF45 with local extrapolation: the 5th-order solution advances, the 4th-order one
/// estimates the error. Same stages, one order more accurate per step.
ButcherTableau rungeKuttaFehlberg45Extrapolated();

/// Dormand-Prince 5(4) (Dormand & Prince 1980; Hairer, Norsett & Wanner, Table II.5.2):
/// 7 stages, the 5th-order solution advances, first same as last (6 evaluations a step).
ButcherTableau dormandPrince45();

/// The classical 4-stage, 4th-order Runge-Kutta method (fixed steps only).
ButcherTableau classicalRungeKutta4();

} // namespace capsula::timeint
