#pragma once
// The operator library of the doubly periodic Green's functions: registers in a
// KernelRegistry
//   "Periodic"      the fluid periodic in x and z, unbounded in y (no wall);
//   "PeriodicWall"  the fluid above the no-slip plane y = 0, periodic in x and z;
//   "PeriodicChannel" the fluid between the no-slip planes y = 0 and y = H ('Wall/Channel
//                   height'), periodic in x and z: plane Couette and Poiseuille flow;
// each with its sublist 'Operator/<name>' (Tolerance of the spectral Ewald sums). Their
// factories take the periods from the deck's domain ('Domain/Periodic length x', 'z') and
// refuse what they cannot serve (core::InputError naming the keys): a domain periodic in
// one direction only (the Ewald sums are doubly periodic). Every kernel sums its stresslet
// too, so any viscosity ratio runs (PeriodicFarField.hpp).
// 'Operator/Summation' = Treecode is refused by the operators ("does not support the
// kernel"); Direct (the default) leaves the far field to the kernel's Ewald sums.
#include <capsula/operators/KernelRegistry.hpp>

namespace capsula::periodic {

/// Registers "Periodic", "PeriodicWall" and "PeriodicChannel" (KernelInfo: FluidDomain
/// Unbounded, AboveWall and Channel, periodic = true).
void registerPeriodicKernels(operators::KernelRegistry& registry);

} // namespace capsula::periodic
