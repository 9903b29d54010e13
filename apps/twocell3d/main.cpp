// twocell3d: two (or more) elastic capsules interacting in shear flow above a wall (thesis
// Chapter 6): side by side or in line, at a fixed height or free; per-cell deformation,
// slip and migration velocities and stress, and the pair's separation, relative velocities
// and the gap between the surfaces, with snapshots for ParaView and restart.
//
// The deck names the scene (packages/scene/SceneParameters.hpp, docs/twocell3d.md); the
// run is the same as cell3d's (capsula::scene::runScene), which writes one column per cell
// for every metric and stops cleanly when two cells come closer than 'Cells/Minimum gap'.
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
  options.application = "twocell3d";
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
    "twocell3d",
    "two elastic capsules interacting in shear flow near a wall: separation, relative "
    "velocities, deformation and stress of each",
    {"twocell3d input/twocell3d/demo.xml",
     "mpiexec -n 2 twocell3d input/twocell3d/side-by-side/h2.5-dz0.5-fixed.xml --output out/sbs",
     "twocell3d input/twocell3d/in-line/h1.25-dx1-free.xml --set \"Cells/Minimum gap=0.1\"",
     "twocell3d input/twocell3d/demo.xml --output out/demo --restart out/demo --set \"Time integration/End time=4\"",
     "twocell3d --print-defaults > my_deck.xml"},
    true};
  return core::runApplication(
    argc, argv, app,
    [](const Teuchos::ParameterList& deck) { return scene::validSceneParameters(deck, "twocell3d"); }, run);
}
