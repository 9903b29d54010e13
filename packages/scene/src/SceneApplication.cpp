#include "capsula/scene/SceneApplication.hpp"

#include "capsula/scene/SceneParameters.hpp"
#include "capsula/scene/SceneRun.hpp"

#include <capsula/operators/KernelRegistry.hpp>

#include <string>

namespace capsula::scene {

int runSceneApplication(int argc, char** argv, const core::AppDescription& app)
{
  const std::string name = app.name;
  const auto run = [name](core::RunContext& context) {
    SceneRunOptions options;
    options.application = name;
    options.deckSource = context.deckName;
    options.outputDirectory = context.options.outputDirectory;
    options.restartDirectory = context.options.restartDirectory;
    options.log = context.out;
    const auto kernels = operators::builtInKernels();
    runScene(*context.deck, context.comm, options, kernels);
  };
  return core::runApplication(
    argc, argv, app, [name](const Teuchos::ParameterList& deck) { return validSceneParameters(deck, name); },
    run);
}

} // namespace capsula::scene
