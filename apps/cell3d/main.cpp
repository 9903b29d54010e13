// cell3d: one (or more) elastic capsules in simple shear flow, free or above a plane wall
// (thesis Chapter 5): deformation, slip and migration velocity, footprint, membrane and
// wall shear stress over time, with snapshots for ParaView and restart.
//
// The deck names the scene (packages/scene/SceneParameters.hpp, docs/cell3d.md); this
// driver only wires the command line to capsula::scene::runScene.
#include <capsula/core/Application.hpp>
#include <capsula/operators/KernelRegistry.hpp>
#include <capsula/scene/SceneParameters.hpp>
#include <capsula/scene/SceneRun.hpp>

namespace {

namespace core = capsula::core;
namespace scene = capsula::scene;

void run(core::RunContext& context)
{
  scene::SceneRunOptions options;
  options.application = "cell3d";
  options.deckSource = context.deckName;
  options.outputDirectory = context.options.outputDirectory;
  options.restartDirectory = context.options.restartDirectory;
  options.log = context.out;
  const auto kernels = capsula::operators::builtInKernels();
  scene::runScene(*context.deck, context.comm, options, kernels);
}

} // namespace

int main(int argc, char** argv)
{
  const core::AppDescription app{
    "cell3d",
    "an elastic capsule in shear flow near a wall: deformation, velocities, cell and wall stress",
    {"cell3d input/cell3d/demo.xml",
     "mpiexec -n 2 cell3d input/cell3d/demo.xml --output out/demo",
     "cell3d input/cell3d/demo.xml --set \"Flow/Capillary number=0.6\" --set \"Cells/Cell 0/Mesh level=3\"",
     "cell3d input/cell3d/demo.xml --output out/demo --restart out/demo --set \"Time integration/End time=4\"",
     "cell3d --print-defaults > my_deck.xml"},
    true};
  return core::runApplication(
    argc, argv, app,
    [](const Teuchos::ParameterList& deck) { return scene::validSceneParameters(deck, "cell3d"); }, run);
}
