#include "capsula/operators/KrylovMethod.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>
#include <capsula/core/PassThroughSublist.hpp>

#include <BelosSolverFactory.hpp>
#include <BelosSolverFactory_Tpetra.hpp>
#include <BelosTpetraAdapter.hpp>
#include <BelosTypes.hpp>

#include <algorithm>
#include <cctype>
#include <map>

namespace capsula::operators {

namespace {

using MV = Tpetra::MultiVector<double>;
using OP = Tpetra::Operator<double>;

struct OfferedMethod {
  const char* name;
  const char* description;
};

// The default first. Pseudo Block TFQMR is left out as TFQMR's twin for one right-hand side;
// "Hybrid Block GMRES" (GmresPoly) does not report the residual it reached.
const OfferedMethod kOffered[] = {
    {"Block GMRES", "restarted GMRES (block size 1), one operator application per iteration; it tests the "
                    "least-squares residual and confirms it with the explicit one."},
    {"Pseudo Block GMRES", "the same GMRES in the form Belos writes for independent right-hand sides."},
    {"GCRODR", "GMRES that keeps 'Num Recycled Blocks' harmonic Ritz vectors from one restart cycle to the "
               "next (deflated restarting), within one solve."},
    {"TFQMR", "transpose-free QMR: no stored Krylov basis, two operator applications per iteration; "
              "its residual estimate is confirmed with the explicit residual."},
    {"BiCGStab", "stabilised bi-conjugate gradients: no stored Krylov basis, two operator applications per "
                 "iteration; it stops on its recursively updated residual."},
};

std::string upperCase(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::toupper(c); });
  return text;
}

// TFQMR's own test is on an estimate of the residual (a bound from its quasi-residual);
// Belos confirms it with the explicit residual only when asked.
bool confirmsExplicitlyOnRequest(const std::string& method)
{
  return upperCase(method) == "TFQMR";
}

std::string offeredList()
{
  std::string text;
  for (const std::string& name : krylovMethods()) {
    text += (text.empty() ? "" : ", ") + name;
  }
  return text;
}

} // namespace

const std::vector<std::string>& krylovMethods()
{
  static const std::vector<std::string> names = [] {
    Belos::SolverFactory<double, MV, OP> factory;
    const Teuchos::Array<std::string> supported = factory.supportedSolverNames();
    std::vector<std::string> offered;
    for (const OfferedMethod& method : kOffered) {
      const bool known = std::any_of(supported.begin(), supported.end(), [&](const std::string& name) {
        return upperCase(name) == upperCase(method.name);
      });
      if (known) {
        offered.emplace_back(method.name);
      }
    }
    core::require(!offered.empty() && offered.front() == SolverParameters{}.method, "internal: this Belos has no '",
                  SolverParameters{}.method, "' solver");
    return offered;
  }();
  return names;
}

void declareKrylovMethod(Teuchos::ParameterList& solver)
{
  std::string doc = "The Krylov method of the viscosity-ratio equation (used only when some cell has lambda != 1), "
                    "by its name in Belos's solver factory.";
  const auto& offered = krylovMethods();
  for (const OfferedMethod& method : kOffered) {
    if (std::find(offered.begin(), offered.end(), method.name) != offered.end()) {
      doc += std::string(" ") + method.name + ": " + method.description;
    }
  }
  doc += " 'Solver/Tolerance', 'Restart' and 'Maximum iterations' apply to each that has the parameter. The "
         "stage solves of the stiff time integrators keep flexible GMRES ('Solver/Stiff'). docs/operators.md "
         "compares the methods.";
  core::declareChoice(solver, "Method", SolverParameters{}.method, krylovMethods(), doc);
}

void declareBelosParameters(Teuchos::ParameterList& solver)
{
  core::declarePassThroughSublist(
      solver, "Belos",
      "Parameters handed to the Belos solver of 'Solver/Method' as Belos names them (e.g. 'Orthogonalization' = "
      "DGKS, 'Num Recycled Blocks' for GCRODR, 'Implicit Tolerance Scale Factor' for TFQMR). They replace those "
      "Capsula derives from 'Solver/Tolerance' ('Convergence Tolerance'), 'Restart' ('Num Blocks'), 'Maximum "
      "iterations' ('Maximum Iterations', 'Maximum Restarts') and the residual scaling ('Norm of RHS'). Each "
      "entry is checked at start-up against the parameters the chosen solver declares; a key it does not have is "
      "refused.");
}

Teuchos::RCP<const Teuchos::ParameterList> belosValidParameters(const std::string& method)
{
  // Asked once per solve: Belos builds a solver manager to answer, so keep the answers.
  static std::map<std::string, Teuchos::RCP<const Teuchos::ParameterList>> known;
  const auto found = known.find(method);
  if (found != known.end()) {
    return found->second;
  }
  Belos::SolverFactory<double, MV, OP> factory;
  core::require<core::InputError>(factory.isSupported(method), "This Belos has no solver named '", method,
                                  "'; 'Solver/Method' takes ", offeredList(), ".");
  const auto valid = factory.create(method, Teuchos::parameterList())->getValidParameters();
  known.emplace(method, valid);
  return valid;
}

Teuchos::ParameterList checkedBelosEntries(const Teuchos::ParameterList& belos, const std::string& method)
{
  Teuchos::ParameterList entries = belos;
  core::checkPassThroughEntries(entries, *belosValidParameters(method), "Solver/Belos",
                                "the Belos solver '" + method + "' ('Solver/Method')");
  return entries;
}

Teuchos::RCP<Teuchos::ParameterList> belosSettings(const SolverParameters& parameters, const std::string& method,
                                                   const Teuchos::ParameterList& passThrough)
{
  const auto valid = belosValidParameters(method);
  auto list = Teuchos::rcp(new Teuchos::ParameterList(method));
  const auto offer = [&](const std::string& key, const auto& value) {
    if (valid->isParameter(key)) {
      list->set(key, value);
    }
  };
  offer("Convergence Tolerance", parameters.tolerance);
  offer("Num Blocks", parameters.restart);
  offer("Maximum Iterations", parameters.maximumIterations);
  offer("Implicit Residual Scaling", std::string("Norm of RHS"));
  offer("Explicit Residual Scaling", std::string("Norm of RHS"));
  if (confirmsExplicitlyOnRequest(method)) {
    offer("Explicit Residual Test", true);
  }
  offer("Verbosity", static_cast<int>(Belos::Errors + Belos::Warnings));
  list->setParameters(passThrough);
  if (valid->isParameter("Maximum Restarts") && !passThrough.isParameter("Maximum Restarts")) {
    list->set("Maximum Restarts", list->get<int>("Maximum Iterations") / list->get<int>("Num Blocks") + 1);
  }
  return list;
}

void validateKrylovSettings(const SolverParameters& parameters)
{
  const auto& offered = krylovMethods();
  core::require<core::InputError>(std::find(offered.begin(), offered.end(), parameters.method) != offered.end(),
                                  "'Solver/Method' = '", parameters.method, "' is not offered; use one of ",
                                  offeredList(), ".");
  const Teuchos::ParameterList entries = checkedBelosEntries(parameters.belos, parameters.method);
  // Belos checks values (a scaling it does not know, a recycle space as large as the
  // restart length) when it takes them: try them now, not at the first lambda != 1 solve.
  Belos::SolverFactory<double, MV, OP> factory;
  try {
    factory.create(parameters.method, belosSettings(parameters, parameters.method, entries));
  } catch (const std::exception& e) {
    throw core::InputError("The Belos solver '" + parameters.method +
                           "' refuses its settings ('Solver/Tolerance', 'Restart', 'Maximum iterations' and "
                           "'Solver/Belos'): " +
                           core::lastLineOf(e.what()));
  }
}

} // namespace capsula::operators
