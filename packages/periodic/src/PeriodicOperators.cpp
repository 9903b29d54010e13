#include "capsula/periodic/PeriodicOperators.hpp"

namespace capsula::operators {

template class LayerPotentials<periodic::PeriodicFreeSpaceKernel>;
template class LayerPotentials<periodic::PeriodicWallKernel>;
template class LayerPotentials<periodic::PeriodicChannelKernel>;
template class KernelBoundaryIntegralSolver<periodic::PeriodicFreeSpaceKernel>;
template class KernelBoundaryIntegralSolver<periodic::PeriodicWallKernel>;
template class KernelBoundaryIntegralSolver<periodic::PeriodicChannelKernel>;

} // namespace capsula::operators
