#pragma once
// The operator library of the doubly periodic Green's functions: registers in a
// KernelRegistry
//   "Periodic"      the fluid periodic in x and z, unbounded in y (no wall);
//   "PeriodicWall"  the fluid above the no-slip plane y = 0, periodic in x and z;
// each with its sublist 'Operator/<name>' (Tolerance of the spectral Ewald sums). Their
// factories take the periods from the deck's domain ('Domain/Periodic length x', 'z') and
// refuse what they cannot serve (core::InputError naming the keys): a domain periodic in
// one direction only (the Ewald sums are doubly periodic), and for PeriodicWall a viscosity
// ratio other than 1 (its stresslet has only a reference sum, O(N M) with hundreds of
// Fourier modes per pair, too slow for a double layer applied at every GMRES iteration).
// 'Operator/Summation' = Treecode is refused by the operators ("does not support the
// kernel"); Direct (the default) leaves the far field to the kernel's Ewald sums.
#include <capsula/operators/KernelRegistry.hpp>

namespace capsula::periodic {

/// Registers "Periodic" and "PeriodicWall" (KernelInfo: FluidDomain Unbounded and
/// AboveWall, periodic = true).
void registerPeriodicKernels(operators::KernelRegistry& registry);

} // namespace capsula::periodic
