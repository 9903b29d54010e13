#include "capsula/fastsum/TreecodeRegistration.hpp"

#include "capsula/fastsum/TreecodeBackEnd.hpp"

#include <capsula/core/ParameterDeclaration.hpp>

namespace capsula::fastsum {

Teuchos::RCP<const Teuchos::ParameterList> validTreecodeParameters()
{
  auto treecode = Teuchos::rcp(new Teuchos::ParameterList("Treecode"));
  const TreecodeParameters defaults;
  core::declareReal(*treecode, "Tolerance", 1e-5,
                    "Relative error (2-norm over the targets) allowed in the regular sums; sets the "
                    "interpolation degree, the acceptance parameter theta and the precision of the "
                    "single layer's sums (float from 1e-6 up, whose round-off of ~1e-7 it then "
                    "allows) from a measured table (docs/fastsum.md). One node's error, also where "
                    "cells nearly touch, stays below max(2 x this, 3e-6) of the largest velocity "
                    "(3e-6: the float round-off; 1e-7 sums in double). 1e-5 keeps it below the "
                    "discretisation error at level 3 (~1e-4). Has no effect under another "
                    "'Operator/Summation': a value other than the default is refused there.",
                    core::atLeast(1e-7), core::atMost(1e-1));
  core::declareInt(*treecode, "Leaf size", defaults.leafSize,
                   "Most quadrature points in a leaf cluster of the source tree; smaller leaves mean "
                   "more proxy interactions and fewer direct ones. Only the speed depends on it.",
                   1, 100000);
  return treecode;
}

void registerTreecodeSummation(operators::SummationRegistry& summations)
{
  summations.add(
      "Treecode",
      "a barycentric Lagrange treecode (Wang, Tlupova & Krasny 2020) to 'Operator/Treecode/Tolerance', O(M log N).",
      [](const Teuchos::ParameterList& treecode) -> std::shared_ptr<const operators::FarFieldBackEnd> {
        TreecodeParameters parameters = treecodeParametersForTolerance(treecode.get<double>("Tolerance"));
        parameters.leafSize = treecode.get<int>("Leaf size");
        return std::make_shared<TreecodeBackEnd>(parameters);
      },
      validTreecodeParameters());
}

} // namespace capsula::fastsum
