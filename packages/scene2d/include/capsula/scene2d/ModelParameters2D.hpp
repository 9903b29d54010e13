#pragma once
// The deck keys of the 2D tethered-cell model, declared by the components that read them:
//   Flow, Wall                 FlowModel2D.hpp
//   Operator                   operators/KernelChoice.hpp (Kernel, from a KernelRegistry2D)
//   Cell                       CellContour2D.hpp (Membrane law, from a MembraneLawRegistry2D)
//   Tether                     TetherProcedure2D.hpp
//   Discretisation             scene2d/ContourDiscretisation2D.hpp
//   Solver                     operators/OperatorParameters.hpp (the Krylov solve, lambda != 1)
// The run adds Time integration and Output (scene2d/Tether2DDeck.hpp assembles the deck of
// tether2d).
#include "capsula/scene2d/KernelRegistry2D.hpp"
#include "capsula/scene2d/MembraneLawRegistry2D.hpp"

#include <Teuchos_ParameterList.hpp>

namespace capsula::scene2d {

/// Declares the sublists above in `valid`, in that order; 'Operator/Kernel' chooses among
/// `kernels`, 'Cell/Membrane law' among `laws`.
void declareModelParameters2D(Teuchos::ParameterList& valid, const KernelRegistry2D& kernels = builtInKernels2D(),
                              const MembraneLawRegistry2D& laws = builtInMembraneLaws2D());

} // namespace capsula::scene2d
