#include "capsula/operators/BuiltInKernels.hpp"

namespace capsula::operators {

template class LayerPotentials<FreeSpace3DKernel>;
template class LayerPotentials<Wall3DKernel>;
template class KernelBoundaryIntegralSolver<FreeSpace3DKernel>;
template class KernelBoundaryIntegralSolver<Wall3DKernel>;

} // namespace capsula::operators
