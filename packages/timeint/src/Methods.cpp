// The integration methods by their deck names.
#include "capsula/timeint/TimeIntegrator.hpp"

#include "capsula/core/Error.hpp"

namespace capsula::timeint {

std::string toString(Method method)
{
  switch (method) {
  case Method::RKF45:
    return "RKF45";
  case Method::DormandPrince45:
    return "DormandPrince45";
  case Method::RK4:
    return "RK4";
  case Method::ROS34PW2:
    return "ROS34PW2";
  case Method::ROS2:
    return "ROS2";
  case Method::Auto:
    return "Auto";
  }
  return "RKF45";
}

std::vector<Method> allMethods()
{
  return {Method::RKF45, Method::DormandPrince45, Method::RK4, Method::ROS34PW2, Method::ROS2, Method::Auto};
}

bool needsLinearisedSystem(Method method)
{
  return method == Method::ROS34PW2 || method == Method::ROS2 || method == Method::Auto;
}

Method methodFromString(const std::string& word)
{
  std::string names;
  for (const auto m : allMethods()) {
    if (word == toString(m)) {
      return m;
    }
    names += (names.empty() ? "" : ", ") + toString(m);
  }
  throw core::InputError("Unknown time-integration method '" + word + "': use one of " + names + ".");
}

} // namespace capsula::timeint
