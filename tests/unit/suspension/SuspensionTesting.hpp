#pragma once
// The domain of the suspension tests: a channel periodic along x and z.
#include <capsula/domain/Domain.hpp>

namespace capsula::suspension::testing {

inline domain::Domain periodicChannel(double lx, double height, double lz)
{
  domain::DomainShape shape;
  shape.channelHeight = height;
  shape.periodX = lx;
  shape.periodZ = lz;
  return domain::Domain(shape);
}

} // namespace capsula::suspension::testing
