#pragma once
// A configured far-field back-end ('Operator/Summation' and its own settings) that makes a
// FarFieldSummation for each kernel policy it supports. The layer potentials of kernel K
// ask it for K (by type) when they are built; DiscretisationParameters::farField carries
// it, null meaning DirectSummation. A back-end from a later package (fastsum's treecode)
// implements this, so the operators never name it.
#include <capsula/operators/FarFieldSummation.hpp>

#include <memory>
#include <string>
#include <typeindex>

namespace capsula::operators {

class FarFieldBackEnd {
public:
  virtual ~FarFieldBackEnd() = default;
  /// The deck name ('Operator/Summation').
  virtual std::string name() const = 0;
  /// A summation for the kernel policy `kernel` (named `kernelName` in messages), or null
  /// when the back-end does not support that kernel.
  virtual std::unique_ptr<FarFieldSummation> forKernel(std::type_index kernel, const std::string& kernelName) const = 0;
};

} // namespace capsula::operators
