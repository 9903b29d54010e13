#include "capsula/operators/JacobianProducts.hpp"

#include <cmath>

namespace capsula::operators {

namespace {

double dot(const std::vector<double>& a, const std::vector<double>& b)
{
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    s += a[i] * b[i];
  }
  return s;
}

// A column whose part outside the span of the earlier ones is below this fraction of its
// length adds nothing the earlier ones do not give, and would make c large and r0
// inaccurate by cancellation: it is left out.
constexpr double kDependentColumn = 1e-8;

} // namespace

void JacobianProducts::clear()
{
  x_.clear();
  Jx_.clear();
  oldest_ = 0;
}

void JacobianProducts::add(const double* x, const double* Jx, std::size_t n)
{
  if (capacity_ == 0) {
    return;
  }
  if (x_.size() < capacity_) {
    x_.emplace_back(x, x + n);
    Jx_.emplace_back(Jx, Jx + n);
    return;
  }
  x_[oldest_].assign(x, x + n);
  Jx_[oldest_].assign(Jx, Jx + n);
  oldest_ = (oldest_ + 1) % capacity_;
}

double JacobianProducts::minimalResidualGuess(double shift, const std::vector<double>& r, std::vector<double>& x0,
                                              std::vector<double>& r0) const
{
  const std::size_t n = r.size();
  // Orthonormalise the columns a_j = W x_j (Gram-Schmidt, twice: one pass loses
  // orthogonality when the columns are nearly dependent), keeping R of A = Q R.
  std::vector<std::vector<double>> q;
  std::vector<std::vector<double>> rColumns; // R's column of each kept a_j, length q.size()
  std::vector<std::size_t> kept;
  for (std::size_t j = 0; j < x_.size(); ++j) {
    std::vector<double> a(n);
    for (std::size_t i = 0; i < n; ++i) {
      a[i] = x_[j][i] - shift * Jx_[j][i];
    }
    const double length = std::sqrt(dot(a, a));
    if (length == 0.0) {
      continue;
    }
    std::vector<double> coefficients(q.size(), 0.0);
    for (int pass = 0; pass < 2; ++pass) {
      for (std::size_t k = 0; k < q.size(); ++k) {
        const double p = dot(q[k], a);
        coefficients[k] += p;
        for (std::size_t i = 0; i < n; ++i) {
          a[i] -= p * q[k][i];
        }
      }
    }
    const double rest = std::sqrt(dot(a, a));
    if (rest <= kDependentColumn * length) {
      continue;
    }
    for (double& v : a) {
      v /= rest;
    }
    coefficients.push_back(rest);
    q.push_back(std::move(a));
    rColumns.push_back(std::move(coefficients));
    kept.push_back(j);
  }
  // R c = Q^T r by back substitution (R upper triangular: column k has k + 1 entries).
  const std::size_t m = q.size();
  std::vector<double> c(m);
  for (std::size_t k = 0; k < m; ++k) {
    c[k] = dot(q[k], r);
  }
  for (std::size_t k = m; k-- > 0;) {
    for (std::size_t l = k + 1; l < m; ++l) {
      c[k] -= rColumns[l][k] * c[l];
    }
    c[k] /= rColumns[k][k];
  }
  x0.assign(n, 0.0);
  r0 = r;
  for (std::size_t k = 0; k < m; ++k) {
    const std::vector<double>& x = x_[kept[k]];
    const std::vector<double>& Jx = Jx_[kept[k]];
    for (std::size_t i = 0; i < n; ++i) {
      x0[i] += c[k] * x[i];
      r0[i] -= c[k] * (x[i] - shift * Jx[i]);
    }
  }
  return std::sqrt(dot(r0, r0));
}

} // namespace capsula::operators
