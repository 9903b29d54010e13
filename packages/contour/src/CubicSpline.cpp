#include "capsula/contour/CubicSpline.hpp"

#include "capsula/contour/Tridiagonal.hpp"

#include <capsula/core/Error.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace capsula::contour {

namespace {

using core::InputError;
using core::require;

std::size_t checkedPieces(const std::vector<double>& knots, std::size_t minimumPieces, const char* kind)
{
  require<InputError>(knots.size() >= minimumPieces + 1, "a ", kind, " cubic spline needs at least ", minimumPieces + 1,
                      " knots, got ", knots.size());
  for (std::size_t k = 0; k + 1 < knots.size(); ++k) {
    require<InputError>(std::isfinite(knots[k]) && std::isfinite(knots[k + 1]) && knots[k + 1] > knots[k],
                        "cubic spline knots must be finite and strictly increasing; knot ", k + 1, " (", knots[k + 1],
                        ") does not exceed knot ", k, " (", knots[k], ")");
  }
  return knots.size() - 1;
}

std::vector<double> spacings(const std::vector<double>& knots)
{
  std::vector<double> h(knots.size() - 1);
  for (std::size_t k = 0; k < h.size(); ++k) {
    h[k] = knots[k + 1] - knots[k];
  }
  return h;
}

/// Right-hand side of eq A.21 at interior knot i: 6 (divided difference jump).
double jumpOfSlopes(const std::vector<double>& y, const std::vector<double>& h, std::size_t i)
{
  return 6.0 * ((y[i + 1] - y[i]) / h[i] - (y[i] - y[i - 1]) / h[i - 1]);
}

} // namespace

CubicSpline::CubicSpline(std::vector<double> knots, SplineEnds ends) : knots_(std::move(knots)), ends_(ends) {}

void CubicSpline::buildPieces(const std::vector<double>& y, const std::vector<double>& m)
{
  const std::vector<double> h = spacings(knots_);
  pieces_.resize(h.size());
  for (std::size_t k = 0; k < h.size(); ++k) {
    CubicPiece& p = pieces_[k];
    p.a = (m[k + 1] - m[k]) / (6.0 * h[k]);                                // eq A.22
    p.b = 0.5 * m[k];                                                      // eq A.23
    p.c = (y[k + 1] - y[k]) / h[k] - h[k] * (2.0 * m[k] + m[k + 1]) / 6.0; // eq A.24
    p.d = y[k];                                                            // eq A.25 (ERRATA)
  }
}

CubicSpline CubicSpline::periodic(std::vector<double> knots, const std::vector<double>& values)
{
  const std::size_t n = checkedPieces(knots, 3, "periodic");
  require<InputError>(values.size() == n, "a periodic cubic spline over ", n + 1, " knots takes ", n,
                      " values (one per piece), got ", values.size());
  CubicSpline spline(std::move(knots), SplineEnds::Periodic);
  const std::vector<double> h = spacings(spline.knots_);
  std::vector<double> y(values);
  y.push_back(values.front());

  // Eq A.21 at every knot, indices modulo n: a cyclic tridiagonal system for M_0..M_{n-1}.
  std::vector<double> lower(n), diagonal(n), upper(n), m(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t previous = (i + n - 1) % n;
    lower[i] = h[previous];
    diagonal[i] = 2.0 * (h[previous] + h[i]);
    upper[i] = h[i];
    const double slopeBefore = (y[i] - y[previous]) / h[previous];
    m[i] = 6.0 * ((y[i + 1] - y[i]) / h[i] - slopeBefore);
  }
  solveCyclicTridiagonal(lower, diagonal, upper, m);
  m.push_back(m.front());
  spline.buildPieces(y, m);
  return spline;
}

CubicSpline CubicSpline::natural(std::vector<double> knots, const std::vector<double>& values)
{
  const std::size_t n = checkedPieces(knots, 1, "natural");
  require<InputError>(values.size() == n + 1, "an open cubic spline over ", n + 1, " knots takes ", n + 1,
                      " values, got ", values.size());
  CubicSpline spline(std::move(knots), SplineEnds::Natural);
  const std::vector<double> h = spacings(spline.knots_);

  // M_0 = M_n = 0 (eqs A.31-A.32); eq A.21 for the interior M_1..M_{n-1}.
  std::vector<double> m(n + 1, 0.0);
  if (n >= 2) {
    const std::size_t interior = n - 1;
    std::vector<double> lower(interior), diagonal(interior), upper(interior), rhs(interior);
    for (std::size_t i = 1; i < n; ++i) {
      lower[i - 1] = h[i - 1];
      diagonal[i - 1] = 2.0 * (h[i - 1] + h[i]);
      upper[i - 1] = h[i];
      rhs[i - 1] = jumpOfSlopes(values, h, i);
    }
    solveTridiagonal(lower, diagonal, upper, rhs);
    std::copy(rhs.begin(), rhs.end(), m.begin() + 1);
  }
  spline.buildPieces(values, m);
  return spline;
}

CubicSpline CubicSpline::clamped(std::vector<double> knots, const std::vector<double>& values, double startSlope,
                                 double endSlope)
{
  const std::size_t n = checkedPieces(knots, 1, "clamped");
  require<InputError>(values.size() == n + 1, "an open cubic spline over ", n + 1, " knots takes ", n + 1,
                      " values, got ", values.size());
  require<InputError>(std::isfinite(startSlope) && std::isfinite(endSlope),
                      "clamped cubic spline: the end slopes must be finite, got ", startSlope, " and ", endSlope);
  CubicSpline spline(std::move(knots), SplineEnds::Clamped);
  const std::vector<double> h = spacings(spline.knots_);

  // Rows 0 and n impose p'(s_0) and p'(s_n) through eq A.24; rows 1..n-1 are eq A.21.
  std::vector<double> lower(n + 1, 0.0), diagonal(n + 1, 0.0), upper(n + 1, 0.0), m(n + 1, 0.0);
  for (std::size_t i = 0; i <= n; ++i) {
    if (i == 0) {
      diagonal[i] = 2.0 * h[i];
      upper[i] = h[i];
      m[i] = 6.0 * ((values[i + 1] - values[i]) / h[i] - startSlope);
    } else if (i == n) {
      lower[i] = h[i - 1];
      diagonal[i] = 2.0 * h[i - 1];
      m[i] = 6.0 * (endSlope - (values[i] - values[i - 1]) / h[i - 1]);
    } else {
      lower[i] = h[i - 1];
      diagonal[i] = 2.0 * (h[i - 1] + h[i]);
      upper[i] = h[i];
      m[i] = jumpOfSlopes(values, h, i);
    }
  }
  solveTridiagonal(lower, diagonal, upper, m);
  spline.buildPieces(values, m);
  return spline;
}

CubicSpline CubicSpline::notAKnot(std::vector<double> knots, const std::vector<double>& values)
{
  const std::size_t n = checkedPieces(knots, 3, "not-a-knot");
  require<InputError>(values.size() == n + 1, "an open cubic spline over ", n + 1, " knots takes ", n + 1,
                      " values, got ", values.size());
  CubicSpline spline(std::move(knots), SplineEnds::NotAKnot);
  const std::vector<double> h = spacings(spline.knots_);

  // A continuous third derivative at s_1 means h_1 M_0 - (h_0 + h_1) M_1 + h_0 M_2 = 0.
  // Eliminating M_0 (and, at the other end, M_n) from eq A.21 at s_1 (s_{n-1}) leaves a
  // tridiagonal system for M_1..M_{n-1}:
  //   (h_0 + 2 h_1) M_1 + (h_1 - h_0) M_2 = h_1 r_1 / (h_0 + h_1), and its mirror image.
  const std::size_t interior = n - 1;
  std::vector<double> lower(interior), diagonal(interior), upper(interior), rhs(interior);
  for (std::size_t i = 1; i < n; ++i) {
    lower[i - 1] = h[i - 1];
    diagonal[i - 1] = 2.0 * (h[i - 1] + h[i]);
    upper[i - 1] = h[i];
    rhs[i - 1] = jumpOfSlopes(values, h, i);
  }
  const double h0 = h[0];
  const double h1 = h[1];
  const double hLast = h[n - 1];
  const double hBeforeLast = h[n - 2];
  const double rFirst = rhs.front();
  const double rLast = rhs.back();
  diagonal.front() = h0 + 2.0 * h1;
  upper.front() = h1 - h0;
  rhs.front() = h1 * rFirst / (h0 + h1);
  diagonal.back() = hLast + 2.0 * hBeforeLast;
  lower.back() = hBeforeLast - hLast;
  rhs.back() = hBeforeLast * rLast / (hBeforeLast + hLast);
  solveTridiagonal(lower, diagonal, upper, rhs);

  std::vector<double> m(n + 1);
  std::copy(rhs.begin(), rhs.end(), m.begin() + 1);
  m[0] = ((h0 + h1) * m[1] - h0 * m[2]) / h1;
  m[n] = ((hBeforeLast + hLast) * m[n - 1] - hLast * m[n - 2]) / hBeforeLast;
  spline.buildPieces(values, m);
  return spline;
}

CubicSpline CubicSpline::interpolating(std::vector<double> knots, const std::vector<double>& values)
{
  for (std::size_t k = 0; k < values.size(); ++k) {
    require<InputError>(std::isfinite(values[k]), "cubic spline: value ", k, " is not finite");
  }
  if (knots.size() >= 4) {
    return notAKnot(std::move(knots), values);
  }
  const std::size_t n = checkedPieces(knots, 1, "interpolating");
  require<InputError>(values.size() == n + 1, "an open cubic spline over ", n + 1, " knots takes ", n + 1,
                      " values, got ", values.size());
  CubicSpline spline(std::move(knots), SplineEnds::NotAKnot);
  const std::vector<double> h = spacings(spline.knots_);
  // The line has M = 0; the parabola through three samples the constant M = 2 c, c its
  // second divided difference.
  double m = 0.0;
  if (n == 2) {
    m = 2.0 * ((values[2] - values[1]) / h[1] - (values[1] - values[0]) / h[0]) / (h[0] + h[1]);
  }
  spline.buildPieces(values, std::vector<double>(n + 1, m));
  return spline;
}

std::pair<int, double> CubicSpline::locate(double s) const
{
  const double start = knots_.front();
  if (ends_ == SplineEnds::Periodic) {
    const double period = range();
    double wrapped = std::fmod(s - start, period);
    if (wrapped < 0.0) {
      wrapped += period;
    }
    s = start + wrapped;
  }
  const auto after = std::upper_bound(knots_.begin(), knots_.end(), s);
  const long index = static_cast<long>(after - knots_.begin()) - 1;
  const long last = static_cast<long>(pieces_.size()) - 1;
  const int k = static_cast<int>(std::clamp(index, 0L, last));
  return {k, s - knots_[static_cast<std::size_t>(k)]};
}

double CubicSpline::value(double s) const
{
  const auto [k, ds] = locate(s);
  return piece(k).value(ds);
}

double CubicSpline::derivative(double s) const
{
  const auto [k, ds] = locate(s);
  return piece(k).derivative(ds);
}

double CubicSpline::secondDerivative(double s) const
{
  const auto [k, ds] = locate(s);
  return piece(k).secondDerivative(ds);
}

int stationaryPoints(const CubicPiece& p, double span, double roots[2])
{
  const double qa = 3.0 * p.a;
  const double qb = 2.0 * p.b;
  const double qc = p.c;
  double candidates[2];
  int count = 0;
  const double scale = std::abs(qa) * span * span + std::abs(qb) * span + std::abs(qc);
  if (std::abs(qa) * span * span <= 1e-14 * scale) {
    if (qb != 0.0) {
      candidates[count++] = -qc / qb;
    }
  } else {
    const double discriminant = qb * qb - 4.0 * qa * qc;
    if (discriminant >= 0.0) {
      // Stable form: q = -(b + sign(b) sqrt(D)) / 2, roots q/a and c/q.
      const double q = -0.5 * (qb + std::copysign(std::sqrt(discriminant), qb));
      candidates[count++] = q / qa;
      if (q != 0.0) {
        candidates[count++] = qc / q;
      }
    }
  }
  int inside = 0;
  for (int i = 0; i < count; ++i) {
    if (candidates[i] > 0.0 && candidates[i] < span) {
      roots[inside++] = candidates[i];
    }
  }
  return inside;
}

} // namespace capsula::contour
