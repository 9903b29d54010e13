#pragma once
// The command-line program around a scene run, shared by the apps that differ only in
// their name, description and examples (cell3d, twocell3d): parse the command line, read
// and validate the deck against validSceneRunParameters, run it (runScene) with the
// standard libraries, report errors (core::runApplication). A program with kernels,
// summation back-ends, membrane laws or time methods of its own passes its SceneLibraries.
#include <capsula/core/Application.hpp>
#include <capsula/run/OperatorLibraries.hpp>
#include <capsula/run/SceneLibraries.hpp>

#include <Teuchos_ParameterList.hpp>

#include <string>

namespace capsula::run {

/// Runs the validated scene deck `deck` (runScene) for the program `application` with
/// `libraries`, writing where the command line of `context` says (--output, --restart) and
/// logging to its output.
void runSceneOfCommandLine(const Teuchos::ParameterList& deck, const core::RunContext& context,
                           const std::string& application, const SceneLibraries& libraries);

/// The exit status of the whole program (0 on success, see core::runApplication).
/// `cellsWhenNoneGiven`: the cells of a deck that has none, as --print-defaults shows them.
int runSceneApplication(int argc, char** argv, const core::AppDescription& app, int cellsWhenNoneGiven = 1);

/// The same with the kernels, summation back-ends, membrane laws and time methods of
/// `libraries` (instead of standardSceneLibraries()) in the deck and the run.
int runSceneApplication(int argc, char** argv, const core::AppDescription& app, const SceneLibraries& libraries,
                        int cellsWhenNoneGiven = 1);

/// The same with the operator libraries `libraries` and the built-in laws and methods.
int runSceneApplication(int argc, char** argv, const core::AppDescription& app, const OperatorLibraries& libraries,
                        int cellsWhenNoneGiven = 1);

} // namespace capsula::run
