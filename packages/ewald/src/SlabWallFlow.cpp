// The slab flow driven by one Fourier mode of the far wall's velocity (SlabWallFlow.hpp).
#include "capsula/ewald/SlabWallFlow.hpp"

#include <cmath>

namespace capsula::ewald {

SlabWallFlow::SlabWallFlow(double kx, double kz, double height, const std::complex<double> farWallVelocity[3])
    : kx_(kx), kz_(kz), a_(std::sqrt(kx * kx + kz * kz))
{
  const double a = a_, H = height;
  const std::complex<double> longitudinal = (kx * farWallVelocity[0] + kz * farWallVelocity[2]) / a;
  const std::complex<double> transverse = (-kz * farWallVelocity[0] + kx * farWallVelocity[2]) / a;
  const std::complex<double> normal = farWallVelocity[1];
  const double s = std::sinh(a * H), c = std::cosh(a * H);
  const double f1 = s - a * H * c;
  const double f2 = H * s;
  const double f2Slope = s + a * H * c;
  const double delta = (s - a * H) * (s + a * H);
  const std::complex<double> i(0.0, 1.0);
  transverse_ = transverse / s;
  c1_ = (normal * f2Slope + i * a * longitudinal * f2) / delta;
  c2_ = (a * a * H * s * normal - i * a * longitudinal * f1) / delta;
}

void SlabWallFlow::velocity(double y, std::complex<double> u[3]) const
{
  const double a = a_;
  // sinh and cosh from one exponential (this runs for every target and mode).
  const double growing = std::exp(a * y), decaying = 1.0 / growing;
  const double s = 0.5 * (growing - decaying), c = 0.5 * (growing + decaying);
  const std::complex<double> w = c1_ * (s - a * y * c) + c2_ * (y * s);
  const std::complex<double> wSlope = c1_ * (-a * a * y * s) + c2_ * (s + a * y * c);
  const std::complex<double> longitudinal = std::complex<double>(0.0, 1.0) * wSlope / a;
  const std::complex<double> transverse = transverse_ * s;
  u[0] = (kx_ * longitudinal - kz_ * transverse) / a;
  u[1] = w;
  u[2] = (kz_ * longitudinal + kx_ * transverse) / a;
}

} // namespace capsula::ewald
