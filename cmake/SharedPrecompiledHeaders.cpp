// The translation unit of the shared precompiled-header targets (cmake/CapsulaTargets.cmake):
// it compiles nothing of its own; the target exists to build the headers once for every
// library with the same flags.
