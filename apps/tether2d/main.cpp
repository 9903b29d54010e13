// tether2d: the 2D tethered cell of thesis Chapter 4. A cell (an ellipse of aspect ratio
// a/b, area pi L^2) in shear flow over a wall first deforms freely with its lowest point
// 0.005 above the wall, is then tethered there at its lowest node, and is followed until
// equilibrium or the end time, recording contour length, cell length, tether force,
// leading-edge velocity, area and D12 (docs/tether2d.md).
#include <capsula/core/Application.hpp>
#include <capsula/scene2d/Tether2DDeck.hpp>
#include <capsula/scene2d/TetherRun2D.hpp>

#include <ostream>

namespace {

namespace core = capsula::core;
namespace scene2d = capsula::scene2d;

void runTether(core::RunContext& ctx)
{
  std::string directory = ctx.deck->sublist("Output").get<std::string>("Directory");
  if (ctx.options.outputDirectory) {
    directory = *ctx.options.outputDirectory;
  } else if (ctx.options.restartDirectory) {
    directory = *ctx.options.restartDirectory;
  }
  scene2d::TetherRun2D simulation(ctx.comm, *ctx.deck, ctx.out, ctx.deckName);
  *ctx.out << "tether2d: " << simulation.model().numberOfNodes() << " points, " << simulation.model().kernelName()
           << " Green's function, " << ctx.comm->getSize() << " rank(s)\n";
  const scene2d::TetherRunResult2D result = simulation.run(directory, ctx.options.restartDirectory);
  *ctx.out << "Finished at tau = " << result.finalTime << (result.steady ? " (equilibrium)" : "") << " after "
           << result.steps << " steps\n"
           << "  max tether force F/E     = " << result.maxTetherForce << " at tau = " << result.timeOfMaxTetherForce
           << " (after the tethering transient: " << result.maxTetherForceAfterTransient
           << " at tau = " << result.timeOfMaxTetherForceAfterTransient << ")\n"
           << "  max contour length A/A0  = " << result.maxContourLengthRatio << "\n"
           << "  max cell length L_cell/L = " << result.maxCellLength << "\n"
           << "  final D12                = " << result.final.D12 << "\n"
           << "  max |area drift|         = " << result.maxAbsAreaDrift << "\n";
  if (!directory.empty()) {
    *ctx.out << "Wrote " << directory << "\n";
  }
}

} // namespace

int main(int argc, char** argv)
{
  const core::AppDescription app{
      "tether2d",
      "the 2D tethered cell in wall-bounded shear flow (thesis Chapter 4)",
      {"tether2d input/tether2d/demo.xml --output out/demo",
       "tether2d input/tether2d/study/ab1_lambda1_ca0.25.xml --output out/ab1_l1_ca0.25",
       "tether2d input/tether2d/demo.xml --set \"Flow/Capillary number=0.1\" --output out/demo_ca0.1",
       "tether2d input/tether2d/demo.xml --restart out/demo", "tether2d --print-defaults > my_tether.xml"},
      true};
  return core::runApplication(
      argc, argv, app, [](const Teuchos::ParameterList&) { return scene2d::validTether2DParameters(); }, runTether);
}
