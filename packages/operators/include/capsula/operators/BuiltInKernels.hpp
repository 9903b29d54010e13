#pragma once
// The operators for the built-in Green's functions (ContractedKernels.hpp) are compiled
// once, in this library (src/BuiltInKernels.cpp); users include this header instead of
// instantiating them.
#include <capsula/operators/ContractedKernels.hpp>
#include <capsula/operators/KernelBoundaryIntegralSolver.hpp>
#include <capsula/operators/LayerPotentials.hpp>

namespace capsula::operators {

extern template class LayerPotentials<FreeSpace3DKernel>;
extern template class LayerPotentials<Wall3DKernel>;
extern template class KernelBoundaryIntegralSolver<FreeSpace3DKernel>;
extern template class KernelBoundaryIntegralSolver<Wall3DKernel>;

} // namespace capsula::operators
