// cellshape: build a cell's initial surface from a deck and report its geometry.
//
// The quickest real check of a deck's cell before a long run: element and node
// counts, area, volume, reduced volume, centroid, the equivalent ellipsoid and
// its Taylor deformations, projected areas and mesh quality; for a sphere or an
// ellipsoid also the discretisation error of area and volume against the exact
// values. With --output DIR it writes the validated deck and the report there.
#include <capsula/core/Application.hpp>
#include <capsula/core/Files.hpp>
#include <capsula/core/ParameterDeclaration.hpp>
#include <capsula/core/RunInfo.hpp>
#include <capsula/core/Timers.hpp>
#include <capsula/mesh/CellSurfaceParameters.hpp>
#include <capsula/mesh/EquivalentEllipsoid.hpp>
#include <capsula/mesh/Measures.hpp>
#include <capsula/mesh/MeshQuality.hpp>

#include <cmath>
#include <iomanip>
#include <optional>
#include <ostream>
#include <sstream>

namespace {

namespace core = capsula::core;
namespace mesh = capsula::mesh;

Teuchos::RCP<const Teuchos::ParameterList> validParameters(const Teuchos::ParameterList&)
{
  auto valid = Teuchos::rcp(new Teuchos::ParameterList("cellshape"));
  mesh::declareCellSurfaceParameters(core::declareSublist(*valid, "Cell", "The cell's initial surface."));
  auto& disc = core::declareSublist(*valid, "Discretisation", "Quadrature of the surface integrals.");
  core::declareInt(disc, "Quadrature points", 7,
                   "Points N_Q of the symmetric triangle rule used for area, volume and moments "
                   "(1, 3, 4, 6, 7, 12 or 13).",
                   1, 13);
  auto& output = core::declareSublist(*valid, "Output", "Where to write results.");
  core::declareString(output, "Directory", "",
                      "Directory for deck.xml and geometry.txt (empty: print only). --output overrides it.");
  return valid;
}

// Exact area of an ellipsoid by a converged product Gauss quadrature of the
// surface element over the (theta, phi) parametrisation.
double ellipsoidArea(double a, double b, double c)
{
  const int n = 400;
  double area = 0.0;
  for (int i = 0; i < n; ++i) {
    const double t = M_PI * (i + 0.5) / n; // midpoint rule: spectrally accurate for smooth periodic
    for (int j = 0; j < 2 * n; ++j) {
      const double p = M_PI * (j + 0.5) / n;
      const double st = std::sin(t), ct = std::cos(t), sp = std::sin(p), cp = std::cos(p);
      // |x_t x x_p| for x = (a st cp, b st sp, c ct).
      const double nx = b * c * st * st * cp, ny = a * c * st * st * sp, nz = a * b * st * ct;
      area += std::sqrt(nx * nx + ny * ny + nz * nz);
    }
  }
  return area * (M_PI / n) * (M_PI / n);
}

void run(core::RunContext& ctx)
{
  const auto& cellList = ctx.deck->sublist("Cell");
  const int nq = ctx.deck->sublist("Discretisation").get<int>("Quadrature points");
  std::optional<mesh::SurfaceMesh> built;
  {
    Teuchos::TimeMonitor timing(*core::timer("cellshape: build surface"));
    built.emplace(mesh::buildCellSurface(cellList, "Cell"));
  }
  const mesh::SurfaceMesh& surface = *built;

  Teuchos::TimeMonitor timing(*core::timer("cellshape: measures"));
  const double area = mesh::surfaceArea(surface, nq);
  const double volume = mesh::enclosedVolume(surface, nq);
  const mesh::Vec3 c = mesh::centroid(surface, nq);
  const auto ellipsoid = mesh::equivalentEllipsoid(surface, nq);
  const mesh::Vec3 d = mesh::taylorDeformations(ellipsoid);
  const mesh::Vec3 projected = mesh::projectedAreas(surface, nq);
  const auto quality = mesh::meshQuality(surface);

  std::optional<double> exactArea, exactVolume;
  const std::string& shape = cellList.get<std::string>("Shape");
  if (shape == "Sphere") {
    const double r = cellList.get<double>("Radius");
    exactArea = 4.0 * M_PI * r * r;
    exactVolume = 4.0 * M_PI * r * r * r / 3.0;
  } else if (shape != "Biconcave") {
    const auto& s = cellList.get<Teuchos::Array<double>>("Semi-axes");
    exactArea = ellipsoidArea(s[0], s[1], s[2]);
    exactVolume = 4.0 * M_PI * s[0] * s[1] * s[2] / 3.0;
  }

  std::ostringstream report;
  report << std::setprecision(10);
  report << "Cell: " << shape << ", mesh level " << cellList.get<int>("Mesh level") << ": " << surface.numElements()
         << " elements, " << surface.numNodes() << " nodes, N_Q = " << nq << "\n"
         << "  area                 = " << area << "\n"
         << "  volume               = " << volume << "\n"
         << "  reduced volume       = " << mesh::reducedVolume(area, volume) << "\n"
         << "  centroid             = (" << c[0] << ", " << c[1] << ", " << c[2] << ")\n"
         << "  equivalent ellipsoid = semi-axes (" << ellipsoid.semiAxes[0] << ", " << ellipsoid.semiAxes[1] << ", "
         << ellipsoid.semiAxes[2] << ")\n"
         << "  D12, D13, D23        = " << d[0] << ", " << d[1] << ", " << d[2] << "\n"
         << "  projected area on yz, xz, xy planes = " << projected[0] << ", " << projected[1] << ", " << projected[2]
         << "\n"
         << "  mesh quality         = min angle " << quality.minAngle << " deg, max angle " << quality.maxAngle
         << " deg, max edge ratio " << quality.maxEdgeRatio << "\n";
  if (exactArea) {
    report << std::setprecision(3) << "  discretisation error = area " << (area - *exactArea) / *exactArea
           << ", volume " << (volume - *exactVolume) / *exactVolume << " (relative to the exact " << shape << ")\n";
  }
  *ctx.out << report.str();

  std::string directory = ctx.deck->sublist("Output").get<std::string>("Directory");
  if (ctx.options.outputDirectory) {
    directory = *ctx.options.outputDirectory;
  }
  if (!directory.empty() && ctx.comm->getRank() == 0) {
    core::ensureWritableDirectory(directory);
    core::writeFileAtomically(directory + "/deck.xml",
                              [&](std::ostream& out) { core::writeDeckXml(out, *ctx.deck, false); });
    core::writeFileAtomically(directory + "/geometry.txt", [&](std::ostream& out) {
      out << "# " << core::versionLine() << "\n" << report.str();
    });
    *ctx.out << "Wrote " << directory << "/deck.xml and " << directory << "/geometry.txt\n";
  }
}

} // namespace

int main(int argc, char** argv)
{
  const core::AppDescription app{
      "cellshape",
      "build a cell's initial surface from a deck and report its geometry and discretisation error",
      {"cellshape input/cellshape/red_cell.xml", "cellshape input/cellshape/red_cell.xml --set \"Cell/Mesh level=4\"",
       "cellshape input/cellshape/platelet.xml --output out/platelet", "cellshape --print-defaults > my_cell.xml"},
      false};
  return core::runApplication(argc, argv, app, validParameters, run);
}
