// cell3d: one (or more) elastic capsules in simple shear flow, free or above a plane wall
// (thesis Chapter 5): deformation, slip and migration velocity, footprint, membrane and
// wall shear stress over time, with snapshots for ParaView and restart.
//
// The deck names the scene and its outputs (packages/run/SceneRunDeck.hpp, docs/cell3d.md);
// this driver only names the app (capsula::run::runSceneApplication runs it).
#include <capsula/run/SceneApplication.hpp>

int main(int argc, char** argv)
{
  const capsula::core::AppDescription app{
      "cell3d",
      "an elastic capsule in shear flow near a wall: deformation, velocities, cell and wall stress",
      {"cell3d input/cell3d/demo.xml", "mpiexec -n 2 cell3d input/cell3d/demo.xml --output out/demo",
       "cell3d input/cell3d/demo.xml --set \"Flow/Capillary number=0.6\" --set \"Cells/Cell 0/Mesh level=3\"",
       "cell3d input/cell3d/demo.xml --output out/demo --restart out/demo --set \"Time integration/End time=4\"",
       "cell3d --print-defaults > my_deck.xml"},
      true};
  return capsula::run::runSceneApplication(argc, argv, app);
}
