// curvature_report: accuracy of the three node-curvature methods on an ellipsoid.
//
// For each mesh level, the mean curvature kappa, the Gaussian curvature K and the normal
// of every node by element averaging, CGAL jet fitting and the iterative quadratic fit
// (capsula/mesh/Curvature.hpp), against the exact values of the ellipsoid. The default
// deck is the prolate ellipsoid b/a = 0.5, c/a = 2 of thesis Fig. 5.23. Prints Markdown
// tables (docs/curvature.md is this output); with --output DIR also writes them there.
#include <capsula/core/Application.hpp>
#include <capsula/core/Error.hpp>
#include <capsula/core/Files.hpp>
#include <capsula/core/ParameterDeclaration.hpp>
#include <capsula/core/RunInfo.hpp>
#include <capsula/mesh/Curvature.hpp>
#include <capsula/mesh/EllipsoidCurvature.hpp>
#include <capsula/mesh/Shapes.hpp>

#include <chrono>
#include <cmath>
#include <functional>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace core = capsula::core;
namespace mesh = capsula::mesh;

Teuchos::RCP<const Teuchos::ParameterList> validParameters(const Teuchos::ParameterList&)
{
  auto valid = Teuchos::rcp(new Teuchos::ParameterList("curvature_report"));
  auto& shape = core::declareSublist(*valid, "Ellipsoid", "The surface the estimates are measured on.");
  core::declareRealArray(shape, "Semi-axes", {1.0, 0.5, 2.0}, 3,
                         "Semi-axes (a, b, c) along x, y, z; equal values give a sphere.", core::greaterThan(0.0));
  auto& levels = core::declareSublist(*valid, "Mesh", "The mesh levels n (N_E = 20 * 4^n).");
  core::declareInt(levels, "Coarsest level", 1, "First mesh level of the table.", 0, 6);
  core::declareInt(levels, "Finest level", 4, "Last mesh level of the table.", 0, 6);
  auto& jet = core::declareSublist(*valid, "Jet fit", "CGAL Monge jet fitting.");
  core::declareInt(jet, "Degree", mesh::JetFitOptions{}.degree, "Degree of the fitted polynomial.", 2, 4);
  core::declareInt(jet, "Rings", mesh::JetFitOptions{}.rings, "Neighbourhood rings.", 1, 5);
  auto& quadratic = core::declareSublist(*valid, "Quadratic fit", "Iterative local paraboloid fit.");
  core::declareInt(quadratic, "Rings", mesh::QuadraticFitOptions{}.rings, "Neighbourhood rings.", 1, 5);
  auto& output = core::declareSublist(*valid, "Output", "Where to write results.");
  core::declareString(output, "Directory", "",
                      "Directory for curvature.md (empty: print only). --output overrides it.");
  return valid;
}

struct Errors {
  double mean = 0.0;          // ||kappa_h - kappa||_2 / ||kappa||_2
  double gaussian = 0.0;      // the same for K
  double meanPointwise = 0.0; // RMS of (kappa_h - kappa) / kappa
  double meanMax = 0.0;       // max |kappa_h - kappa| / |kappa|
  double normal = 0.0;        // RMS |n_h - n|
  double seconds = 0.0;
};

Errors measure(const mesh::SurfaceMesh& surface, const mesh::Vec3& semiAxes,
               const std::function<mesh::NodeCurvatures(const mesh::SurfaceMesh&)>& method)
{
  const auto start = std::chrono::steady_clock::now();
  const mesh::NodeCurvatures c = method(surface);
  Errors e;
  e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  double m = 0.0, g = 0.0;
  for (int i = 0; i < surface.numNodes(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    const mesh::Vec3 x = surface.position(i);
    const mesh::CurvaturePair exact = mesh::ellipsoidCurvature(semiAxes, x);
    const double relative = (c.mean[k] - exact.mean) / exact.mean;
    e.mean += std::pow(c.mean[k] - exact.mean, 2);
    m += exact.mean * exact.mean;
    e.gaussian += std::pow(c.gaussian[k] - exact.gaussian, 2);
    g += exact.gaussian * exact.gaussian;
    e.meanPointwise += relative * relative;
    e.meanMax = std::max(e.meanMax, std::abs(relative));
    e.normal += (c.normal[k] - mesh::ellipsoidNormal(semiAxes, x)).squaredNorm();
  }
  const double n = surface.numNodes();
  e.mean = std::sqrt(e.mean / m);
  e.gaussian = std::sqrt(e.gaussian / g);
  e.meanPointwise = std::sqrt(e.meanPointwise / n);
  e.normal = std::sqrt(e.normal / n);
  return e;
}

std::string scientific(double value)
{
  std::ostringstream out;
  out << std::scientific << std::setprecision(2) << value;
  return out.str();
}

std::string fixed(double value, int digits)
{
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << value;
  return out.str();
}

void run(core::RunContext& ctx)
{
  const auto& axes = ctx.deck->sublist("Ellipsoid").get<Teuchos::Array<double>>("Semi-axes");
  const mesh::Vec3 semiAxes(axes[0], axes[1], axes[2]);
  const int coarsest = ctx.deck->sublist("Mesh").get<int>("Coarsest level");
  const int finest = ctx.deck->sublist("Mesh").get<int>("Finest level");
  core::require<core::InputError>(coarsest <= finest, "'Mesh/Coarsest level' = ", coarsest,
                                  " exceeds 'Mesh/Finest level' = ", finest, "; swap them.");
  mesh::JetFitOptions jet;
  jet.degree = ctx.deck->sublist("Jet fit").get<int>("Degree");
  jet.rings = ctx.deck->sublist("Jet fit").get<int>("Rings");
  mesh::QuadraticFitOptions quadratic;
  quadratic.rings = ctx.deck->sublist("Quadratic fit").get<int>("Rings");

  const std::vector<std::pair<std::string, std::function<mesh::NodeCurvatures(const mesh::SurfaceMesh&)>>> methods{
      {"element average", [](const mesh::SurfaceMesh& s) { return mesh::elementAveragedCurvature(s); }},
      {"jet fit (degree " + std::to_string(jet.degree) + ", " + std::to_string(jet.rings) + " rings)",
       [&jet](const mesh::SurfaceMesh& s) { return mesh::jetFitCurvature(s, jet); }},
      {"quadratic fit (" + std::to_string(quadratic.rings) + (quadratic.rings == 1 ? " ring)" : " rings)"),
       [&quadratic](const mesh::SurfaceMesh& s) { return mesh::quadraticFitCurvature(s, quadratic); }}};

  std::vector<int> levels, elements, nodes;
  std::vector<std::vector<Errors>> errors; // [level][method]
  for (int level = coarsest; level <= finest; ++level) {
    const mesh::SurfaceMesh surface = mesh::makeEllipsoid(level, semiAxes);
    levels.push_back(level);
    elements.push_back(surface.numElements());
    nodes.push_back(surface.numNodes());
    errors.emplace_back();
    for (const auto& method : methods) {
      errors.back().push_back(measure(surface, semiAxes, method.second));
    }
  }

  std::ostringstream report;
  const auto table = [&](const std::string& title, const std::function<std::string(const Errors&)>& cell) {
    report << "\n" << title << "\n\n| n | N_E | N_P |";
    for (const auto& method : methods) {
      report << " " << method.first << " |";
    }
    report << "\n|---|---|---|";
    for (std::size_t m = 0; m < methods.size(); ++m) {
      report << "---|";
    }
    report << "\n";
    for (std::size_t l = 0; l < levels.size(); ++l) {
      report << "| " << levels[l] << " | " << elements[l] << " | " << nodes[l] << " |";
      for (const Errors& e : errors[l]) {
        report << " " << cell(e) << " |";
      }
      report << "\n";
    }
  };
  report << "Ellipsoid semi-axes (" << semiAxes[0] << ", " << semiAxes[1] << ", " << semiAxes[2]
         << "); errors over all nodes (vertices and midside nodes).\n";
  table("Relative RMS error of the mean curvature kappa, ||kappa_h - kappa||_2 / ||kappa||_2 "
        "(and of the Gaussian curvature K):",
        [](const Errors& e) { return scientific(e.mean) + " (" + scientific(e.gaussian) + ")"; });
  table("Pointwise relative error of kappa, RMS over the nodes (and maximum):",
        [](const Errors& e) { return scientific(e.meanPointwise) + " (" + scientific(e.meanMax) + ")"; });
  table("RMS error of the unit normal |n_h - n| (and time in milliseconds):",
        [](const Errors& e) { return scientific(e.normal) + " (" + fixed(1e3 * e.seconds, 1) + ")"; });
  if (levels.size() >= 2) {
    report << "\nObserved order of kappa between the two finest levels (error ~ h^p, h halves per level):";
    const std::size_t f = levels.size() - 1;
    for (std::size_t m = 0; m < methods.size(); ++m) {
      report << (m == 0 ? " " : ", ") << methods[m].first << " "
             << fixed(std::log2(errors[f - 1][m].mean / errors[f][m].mean), 2);
    }
    report << ".\n";
  }
  *ctx.out << report.str();

  std::string directory = ctx.deck->sublist("Output").get<std::string>("Directory");
  if (ctx.options.outputDirectory) {
    directory = *ctx.options.outputDirectory;
  }
  if (!directory.empty() && ctx.comm->getRank() == 0) {
    core::ensureWritableDirectory(directory);
    core::writeFileAtomically(directory + "/curvature.md", [&](std::ostream& out) {
      out << "<!-- " << core::versionLine() << " -->\n" << report.str();
    });
    *ctx.out << "Wrote " << directory << "/curvature.md\n";
  }
}

} // namespace

int main(int argc, char** argv)
{
  const core::AppDescription app{
      "curvature_report",
      "accuracy of the element-average, jet-fit and quadratic-fit node curvatures on an ellipsoid",
      {"curvature_report input/curvature_report/prolate_ellipsoid.xml",
       "curvature_report input/curvature_report/prolate_ellipsoid.xml --set \"Jet fit/Degree=3\"",
       "curvature_report input/curvature_report/prolate_ellipsoid.xml --set \"Ellipsoid/Semi-axes={1,1,1}\""},
      false};
  return core::runApplication(argc, argv, app, validParameters, run);
}
