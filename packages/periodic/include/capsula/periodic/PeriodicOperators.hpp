#pragma once
// The operators of the periodic kernels, compiled once in this library
// (src/PeriodicOperators.cpp); users include this header instead of instantiating them.
#include <capsula/operators/KernelBoundaryIntegralSolver.hpp>
#include <capsula/operators/LayerPotentials.hpp>
#include <capsula/periodic/PeriodicKernels.hpp>

namespace capsula::operators {

extern template class LayerPotentials<periodic::PeriodicFreeSpaceKernel>;
extern template class LayerPotentials<periodic::PeriodicWallKernel>;
extern template class LayerPotentials<periodic::PeriodicChannelKernel>;
extern template class KernelBoundaryIntegralSolver<periodic::PeriodicFreeSpaceKernel>;
extern template class KernelBoundaryIntegralSolver<periodic::PeriodicWallKernel>;
extern template class KernelBoundaryIntegralSolver<periodic::PeriodicChannelKernel>;

} // namespace capsula::operators
