#include "capsula/domain/FlowProfile.hpp"

#include <capsula/core/Error.hpp>

#include <sstream>

namespace capsula::domain {

const std::vector<std::string>& flowProfileNames()
{
  static const std::vector<std::string> names{"Shear", "Poiseuille"};
  return names;
}

std::string flowProfileName(FlowProfileKind kind)
{
  return flowProfileNames()[static_cast<std::size_t>(kind)];
}

FlowProfile::FlowProfile(FlowProfileKind kind, const Domain& domain) : kind_(kind), height_(domain.channelHeight())
{
  core::require<core::InputError>(kind != FlowProfileKind::Poiseuille || domain.hasUpperWall(),
                                  "'Flow/Profile' = 'Poiseuille' is the pressure-driven flow of a channel, but "
                                  "'Wall/Channel height' is 0 (no upper wall): give the channel a height, or use "
                                  "'Flow/Profile' = 'Shear'.");
}

double FlowProfile::velocity(double y) const
{
  return kind_ == FlowProfileKind::Poiseuille ? y * (1.0 - y / height_) : y;
}

double FlowProfile::shearRate(double y) const
{
  return kind_ == FlowProfileKind::Poiseuille ? 1.0 - 2.0 * y / height_ : 1.0;
}

double FlowProfile::curvature() const
{
  return kind_ == FlowProfileKind::Poiseuille ? -1.0 / height_ : 0.0;
}

std::array<double, 3> FlowProfile::velocityAt(const double x[3]) const
{
  return {velocity(x[wallNormalAxis]), 0.0, 0.0};
}

std::array<double, 9> FlowProfile::gradientAt(const double x[3]) const
{
  std::array<double, 9> gradient{};
  gradient[3 * flowAxis + wallNormalAxis] = shearRate(x[wallNormalAxis]);
  return gradient;
}

double FlowProfile::fluxPerWidth() const
{
  core::require<core::InputError>(height_ > 0.0, "The flux per unit width of the undisturbed flow is finite "
                                                 "only in a channel ('Wall/Channel height' > 0).");
  // int_0^H y dy = H^2 / 2; int_0^H y (1 - y / H) dy = H^2 / 2 - H^2 / 3 = H^2 / 6.
  return kind_ == FlowProfileKind::Poiseuille ? height_ * height_ / 6.0 : height_ * height_ / 2.0;
}

std::string FlowProfile::describe() const
{
  std::ostringstream out;
  if (kind_ == FlowProfileKind::Poiseuille) {
    out << "plane Poiseuille flow u = k y (1 - y / " << height_ << ")";
  } else if (height_ > 0.0) {
    out << "plane Couette flow u = k y (upper wall sliding at k " << height_ << ")";
  } else {
    out << "simple shear u = k y";
  }
  return out.str();
}

} // namespace capsula::domain
