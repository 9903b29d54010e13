#include "capsula/fastsum/SummationParameters.hpp"

#include "capsula/fastsum/TreecodeBackEnd.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>

namespace capsula::fastsum {

void declareSummationParameters(Teuchos::ParameterList& operatorList)
{
  core::declareChoice(operatorList, "Summation", "Direct", {"Direct", "Treecode"},
                      "How the regular quadrature sums of the single and double layer (every target "
                      "against every quadrature point, O(N M)) are computed. Direct: exactly, "
                      "vectorised. Treecode: a barycentric Lagrange treecode (Wang, Tlupova & Krasny "
                      "2020) to 'Operator/Treecode/Tolerance', O(M log N); the singular and "
                      "near-singular corrections stay exact either way (docs/fastsum.md).");
  Teuchos::ParameterList& treecode =
      core::declareSublist(operatorList, "Treecode", "The treecode of 'Operator/Summation' = Treecode.");
  const TreecodeParameters defaults;
  core::declareReal(treecode, "Tolerance", 1e-5,
                    "Relative error (2-norm over the targets) allowed in the regular sums; sets the "
                    "interpolation degree and the acceptance parameter theta from a measured table "
                    "(docs/fastsum.md). 1e-5 keeps it below the discretisation error at level 3 "
                    "(~1e-4).",
                    core::atLeast(1e-7), core::atMost(1e-1));
  core::declareInt(treecode, "Leaf size", defaults.leafSize,
                   "Most quadrature points in a leaf cluster of the source tree; smaller leaves mean "
                   "more proxy interactions and fewer direct ones. Only the speed depends on it.",
                   1, 100000);
}

std::shared_ptr<const operators::FarFieldBackEnd> readFarFieldBackEnd(const Teuchos::ParameterList& operatorList)
{
  const std::string summation = operatorList.get<std::string>("Summation");
  if (summation == "Direct") {
    return nullptr;
  }
  core::require<core::InputError>(summation == "Treecode", "'Operator/Summation' = ", summation,
                                  " is not a summation; use Direct or Treecode.");
  const Teuchos::ParameterList& treecode = operatorList.sublist("Treecode");
  TreecodeParameters parameters = treecodeParametersForTolerance(treecode.get<double>("Tolerance"));
  parameters.leafSize = treecode.get<int>("Leaf size");
  return std::make_shared<TreecodeBackEnd>(parameters);
}

} // namespace capsula::fastsum
