// suspension3d: a suspension of deformable cells of several types (red cells, platelets,
// leukocytes) in a periodic channel. The deck's 'Suspension' sublist names the types, each a
// count or the hematocrit and the keys of a cell; the cells are placed at random (seeded) at
// the start of every run and restart, and run as any 3D scene (capsula::run::runScene): per-cell
// columns x_c_0, x_c_1, ..., the cell-free layer at each wall, the hematocrit profile and each
// type's wall-normal distribution (packages/run/SuspensionApplication.hpp, docs/suspension3d.md).
#include <capsula/run/SuspensionApplication.hpp>

int main(int argc, char** argv)
{
  const capsula::core::AppDescription app{
      "suspension3d",
      "a suspension of red cells and platelets in a periodic channel: hematocrit profile, cell-free layer, "
      "each cell type's wall-normal distribution",
      {"suspension3d input/suspension3d/demo.xml",
       "mpiexec -n 2 suspension3d input/suspension3d/demo.xml --output out/demo",
       "suspension3d input/suspension3d/demo.xml --set \"Suspension/Hematocrit=0.1\" --set \"Suspension/Seed=2\"",
       "suspension3d input/suspension3d/demo.xml --output out/demo --restart out/demo --set \"Time integration/End "
       "time=1\"",
       "suspension3d --print-defaults > my_deck.xml"},
      true};
  return capsula::run::runSuspensionApplication(argc, argv, app);
}
