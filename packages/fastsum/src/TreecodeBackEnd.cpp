#include "capsula/fastsum/TreecodeBackEnd.hpp"

#include "capsula/fastsum/TreecodeSummation.hpp"

#include <capsula/operators/ContractedKernels.hpp>

namespace capsula::fastsum {

TreecodeBackEnd::TreecodeBackEnd(const TreecodeParameters& parameters) : parameters_(parameters)
{
  validate(parameters_);
}

std::unique_ptr<operators::FarFieldSummation> TreecodeBackEnd::forKernel(std::type_index kernel,
                                                                         const std::string& /*kernelName*/) const
{
  if (kernel == std::type_index(typeid(operators::FreeSpace3DKernel))) {
    return std::make_unique<TreecodeSummation<operators::FreeSpace3DKernel>>(parameters_);
  }
  if (kernel == std::type_index(typeid(operators::Wall3DKernel))) {
    return std::make_unique<TreecodeSummation<operators::Wall3DKernel>>(parameters_);
  }
  return nullptr;
}

} // namespace capsula::fastsum
