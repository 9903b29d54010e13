#include "capsula/run/SceneApplication.hpp"

#include "capsula/run/SceneRunDeck.hpp"
#include "capsula/run/SceneRun.hpp"

#include <capsula/fastsum/SummationParameters.hpp>
#include <capsula/operators/KernelRegistry.hpp>

#include <string>

namespace capsula::run {

int runSceneApplication(int argc, char** argv, const core::AppDescription& app, int cellsWhenNoneGiven)
{
  const std::string name = app.name;
  const auto run = [name](core::RunContext& context) {
    SceneRunOptions options;
    options.application = name;
    options.deckSource = context.deckName;
    options.outputDirectory = context.options.outputDirectory;
    options.restartDirectory = context.options.restartDirectory;
    options.log = context.out;
    auto kernels = operators::builtInKernels();
    kernels.setFarField(fastsum::readFarFieldBackEnd(context.deck->sublist("Operator")));
    runScene(*context.deck, context.comm, options, kernels);
  };
  return core::runApplication(
      argc, argv, app,
      [name, cellsWhenNoneGiven](const Teuchos::ParameterList& deck) {
        return validSceneRunParameters(deck, name, cellsWhenNoneGiven);
      },
      run);
}

} // namespace capsula::run
