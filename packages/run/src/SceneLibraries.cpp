#include "capsula/run/SceneLibraries.hpp"

#include <utility>

namespace capsula::run {

SceneLibraries sceneLibrariesWith(OperatorLibraries operators)
{
  return SceneLibraries{std::move(operators), elasticity::builtInMembraneLaws(), timeint::builtInMethods()};
}

SceneLibraries standardSceneLibraries()
{
  return sceneLibrariesWith(standardOperatorLibraries());
}

} // namespace capsula::run
