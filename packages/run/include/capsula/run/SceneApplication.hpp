#pragma once
// The command-line program around a scene run, shared by the apps that differ only in
// their name, description and examples (cell3d, twocell3d): parse the command line, read
// and validate the deck against validSceneRunParameters, run it (runScene) with the
// standard operator libraries, report errors (core::runApplication). A program with
// kernels or summation back-ends of its own passes its OperatorLibraries.
#include <capsula/core/Application.hpp>
#include <capsula/run/OperatorLibraries.hpp>

namespace capsula::run {

/// The exit status of the whole program (0 on success, see core::runApplication).
/// `cellsWhenNoneGiven`: the cells of a deck that has none, as --print-defaults shows them.
int runSceneApplication(int argc, char** argv, const core::AppDescription& app, int cellsWhenNoneGiven = 1);

/// The same with the kernels and summation back-ends of `libraries` (instead of
/// standardOperatorLibraries()) in the deck and the run.
int runSceneApplication(int argc, char** argv, const core::AppDescription& app, const OperatorLibraries& libraries,
                        int cellsWhenNoneGiven = 1);

} // namespace capsula::run
