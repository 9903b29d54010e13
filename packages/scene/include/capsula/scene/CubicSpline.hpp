#pragma once
// A cubic interpolating spline of samples (t_k, f_k) in time, used for the centroid
// velocity x_c'(t) of thesis Section 3.11.2 ("fitting a cubic spline to x_c = f(t) and
// taking the derivative").
//
// End conditions are "not-a-knot" (the third derivative is continuous at the second and
// the second-to-last sample), so the spline reproduces every cubic exactly and its
// derivative is O(h^3) accurate up to the ends, where the latest output time lies. A
// natural spline would force f'' = 0 at the ends and lose an order there. With fewer
// than four samples the spline is the interpolating polynomial (degree n - 1).
#include <vector>

namespace capsula::scene {

class CubicSpline {
public:
  /// Throws core::InputError unless times are strictly increasing, finite and as many as
  /// values, and there is at least one sample.
  CubicSpline(std::vector<double> times, std::vector<double> values);

  int numSamples() const { return static_cast<int>(times_.size()); }
  double value(double t) const;
  double derivative(double t) const;
  /// f'(t_k) at every sample.
  const std::vector<double>& sampleDerivatives() const { return slopes_; }

private:
  int interval(double t) const;

  std::vector<double> times_, values_;
  std::vector<double> slopes_;   // f'(t_k): the spline in Hermite form
};

} // namespace capsula::scene
