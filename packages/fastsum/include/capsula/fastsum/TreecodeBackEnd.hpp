#pragma once
// The treecode as an operators::FarFieldBackEnd: TreecodeSummation for the built-in
// kernel policies (operators::FreeSpace3DKernel and operators::Wall3DKernel, the ones the
// registry's "FreeSpace" and "Wall" use), instantiated in TreecodeBackEnd.cpp.
#include <capsula/fastsum/TreecodeParameters.hpp>

#include <capsula/operators/FarFieldBackEnd.hpp>

namespace capsula::fastsum {

class TreecodeBackEnd final : public operators::FarFieldBackEnd {
public:
  explicit TreecodeBackEnd(const TreecodeParameters& parameters);
  std::string name() const override { return "Treecode"; }
  const TreecodeParameters& parameters() const { return parameters_; }
  std::unique_ptr<operators::FarFieldSummation> forKernel(std::type_index kernel,
                                                          const std::string& kernelName) const override;

private:
  TreecodeParameters parameters_;
};

} // namespace capsula::fastsum
