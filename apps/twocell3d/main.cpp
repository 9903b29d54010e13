// twocell3d: two (or more) elastic capsules interacting in shear flow above a wall (thesis
// Chapter 6): side by side or in line, at a fixed height or free; per-cell deformation,
// slip and migration velocities and stress, and the pair's separation, relative velocities
// and the gap between the surfaces, with snapshots for ParaView and restart.
//
// The deck names the scene and its outputs (packages/run/SceneRunDeck.hpp,
// docs/twocell3d.md); the run is the same as cell3d's (capsula::run::runScene), which writes one column per cell
// for every metric and stops cleanly when two cells come closer than 'Cells/Minimum gap'.
#include <capsula/run/SceneApplication.hpp>

int main(int argc, char** argv)
{
  const capsula::core::AppDescription app{
      "twocell3d",
      "two elastic capsules interacting in shear flow near a wall: separation, relative "
      "velocities, deformation and stress of each",
      {"twocell3d input/twocell3d/demo.xml",
       "mpiexec -n 2 twocell3d input/twocell3d/side-by-side/h2.5-dz0.5-fixed.xml --output out/sbs",
       "twocell3d input/twocell3d/in-line/h1.25-dx1-free.xml --set \"Cells/Minimum gap=0.1\"",
       "twocell3d input/twocell3d/demo.xml --output out/demo --restart out/demo --set \"Time integration/End time=4\"",
       "twocell3d --print-defaults > my_deck.xml"},
      true};
  return capsula::run::runSceneApplication(argc, argv, app, /*cellsWhenNoneGiven=*/2);
}
