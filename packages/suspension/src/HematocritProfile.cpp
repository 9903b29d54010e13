#include "capsula/suspension/HematocritProfile.hpp"

#include "capsula/suspension/SlabVolumes.hpp"

#include <capsula/core/Error.hpp>

namespace capsula::suspension {

namespace {

void requirePeriodicChannel(const domain::Domain& domain, const char* what)
{
  core::require<core::InputError>(domain.hasUpperWall() && domain.isPeriodic(domain::flowAxis) &&
                                      domain.isPeriodic(domain::vorticityAxis),
                                  "The ", what,
                                  " is measured in a channel periodic along x and z ('Wall/Channel "
                                  "height', 'Domain/Periodic length x' and 'z' all > 0), not in ",
                                  domain.describe(), ".");
}

} // namespace

HematocritProfile hematocritProfile(const std::vector<const mesh::SurfaceMesh*>& cells, const domain::Domain& domain,
                                    int numSlabs)
{
  requirePeriodicChannel(domain, "hematocrit profile");
  return hematocritProfileInSlab(cells, domain.channelHeight(),
                                 domain.period(domain::flowAxis) * domain.period(domain::vorticityAxis), numSlabs);
}

HematocritProfile hematocritProfileInSlab(const std::vector<const mesh::SurfaceMesh*>& cells, double top, double area,
                                          int numSlabs)
{
  core::require<core::InputError>(numSlabs >= 1, "The hematocrit profile needs at least one slab, not ", numSlabs, ".");
  core::require<core::InputError>(top > 0.0 && area > 0.0, "The hematocrit profile needs a slab of positive height ",
                                  "and area, not ", top, " and ", area, ".");
  HematocritProfile profile;
  for (int k = 0; k <= numSlabs; ++k) {
    profile.heights.push_back(top * k / numSlabs);
  }
  profile.fraction.assign(static_cast<std::size_t>(numSlabs), 0.0);
  double total = 0.0;
  for (const mesh::SurfaceMesh* cell : cells) {
    const std::vector<double> volumes = volumesBetweenHeights(*cell, profile.heights);
    for (std::size_t k = 0; k < volumes.size(); ++k) {
      profile.fraction[k] += volumes[k];
      total += volumes[k];
    }
  }
  const double slab = area * top / numSlabs;
  for (double& f : profile.fraction) {
    f /= slab;
  }
  profile.mean = total / (area * top);
  return profile;
}

} // namespace capsula::suspension
