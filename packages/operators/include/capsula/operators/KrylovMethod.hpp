#pragma once
// The Krylov method of the viscosity-ratio equation (lambda != 1), chosen by its Belos name
// ('Solver/Method'), and the settings handed to it: Capsula's keys ('Solver/Tolerance',
// 'Restart', 'Maximum iterations') translated to the Belos parameters the method has,
// overridden by the entries of the pass-through sublist 'Solver/Belos'
// (core/PassThroughSublist.hpp), which are checked at start-up against the chosen method's
// own valid parameters.
//
// The methods offered are the Belos solver managers for a nonsymmetric operator without a
// preconditioner that report the residual they reached (SolverFactory of Trilinos 13.2;
// each is checked against Belos::SolverFactory::supportedSolverNames() when first asked).
// Belos's other names for these solvers are not offered: "GMRES" is Pseudo Block GMRES, and
// "Flexible GMRES" without a right preconditioner is Block GMRES (Belos switches it back).
#include <capsula/operators/OperatorParameters.hpp>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <string>
#include <vector>

namespace capsula::operators {

/// The names 'Solver/Method' accepts, the default (SolverParameters{}.method) first.
const std::vector<std::string>& krylovMethods();

/// Declares 'Method' in `solver`: a choice of krylovMethods(), each described.
void declareKrylovMethod(Teuchos::ParameterList& solver);

/// Declares the pass-through sublist 'Belos' in `solver`.
void declareBelosParameters(Teuchos::ParameterList& solver);

/// The valid parameters of the Belos solver manager `method` (any name Belos's factory
/// takes), as Belos declares them.
Teuchos::RCP<const Teuchos::ParameterList> belosValidParameters(const std::string& method);

/// The entries of a 'Solver/Belos' sublist, checked against belosValidParameters(method)
/// (an int where Belos takes a double converted). Throws core::InputError naming
/// 'Solver/Belos/<key>'.
Teuchos::ParameterList checkedBelosEntries(const Teuchos::ParameterList& belos, const std::string& method);

/// The Belos parameter list of one solve by `method`: from `parameters`, the tolerance on
/// ||b - A x|| / ||b|| ("Norm of RHS" scaling of the implicit and explicit residuals, so that
/// a warm start does not change what "converged" means), the restart length and the
/// iteration cap, each only where the method has that parameter; for TFQMR, the explicit
/// residual's confirmation of its estimate. Then `passThrough` (checked entries of
/// 'Solver/Belos') replaces any of them. Unless it sets "Maximum Restarts", that follows
/// the final iteration cap and restart length, so that the iteration cap is the limit.
Teuchos::RCP<Teuchos::ParameterList> belosSettings(const SolverParameters& parameters, const std::string& method,
                                                   const Teuchos::ParameterList& passThrough);

/// Throws core::InputError naming 'Solver/Method' unless parameters.method is one of
/// krylovMethods(), naming 'Solver/Belos/<key>' for an entry of parameters.belos the method
/// does not take, or naming 'Solver/Belos' when Belos refuses the settings as a whole.
void validateKrylovSettings(const SolverParameters& parameters);

} // namespace capsula::operators
