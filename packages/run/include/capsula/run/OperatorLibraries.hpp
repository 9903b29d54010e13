#pragma once
// The operator libraries a 3D scene application offers: the Green's functions
// ('Operator/Kernel') and the far-field summation back-ends ('Operator/Summation'), each
// by deck name with its own sublist. The application owns them; a program that adds a
// kernel or a back-end registers it here before it declares its deck (docs/extending.md).
#include <capsula/operators/KernelRegistry.hpp>
#include <capsula/operators/SummationRegistry.hpp>

#include <Teuchos_ParameterList.hpp>

namespace capsula::run {

struct OperatorLibraries {
  operators::KernelRegistry kernels;
  operators::SummationRegistry summations;
};

/// What cell3d and twocell3d offer: the built-in kernels (FreeSpace, Wall), the periodic
/// ones (Periodic, PeriodicWall: capsula::periodic), Direct and fastsum's Treecode.
OperatorLibraries standardOperatorLibraries();

/// Declares the deck's "Operator" sublist in `valid`: 'Kernel', 'Summation' and the
/// sublists of the kernels and back-ends with settings.
void declareOperatorLibraryParameters(Teuchos::ParameterList& valid, const OperatorLibraries& libraries);

/// The kernels of `libraries` with the far-field back-end the validated `deck` selects
/// (what a Scene is built from).
operators::KernelRegistry kernelsForDeck(const OperatorLibraries& libraries, const Teuchos::ParameterList& deck);

} // namespace capsula::run
