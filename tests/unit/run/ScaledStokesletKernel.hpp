#pragma once
// A Green's function registered from outside the operators package, as a kernel library
// would: "ScaledFreeSpace", free space in a fluid of viscosity mu / c, c being its one
// setting 'Operator/ScaledFreeSpace/Stokeslet scale'. Its Stokeslet is c times FreeSpace's
// and its stresslet the same, so it is FreeSpace with the membrane load scaled by c, or
// at the capillary number Ca / c: the node velocity is u_inf + c (u_FreeSpace - u_inf)
// with every lambda = 1, a result the tests can check exactly.
#include <capsula/operators/KernelRegistry.hpp>

namespace capsula::run::testing {

/// Registers "ScaledFreeSpace" (unbounded fluid) with the sublist key 'Stokeslet scale'.
void registerScaledStokesletKernel(operators::KernelRegistry& kernels);

} // namespace capsula::run::testing
