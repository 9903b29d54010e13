#pragma once

namespace capsula::operators {

/// How the double layer at a node of a surface treats its principal value.
enum class DoubleLayerForm {
  /// Thesis eq 3.44 with the ERRATA sign: int_Sc [u - u(x0)] T n dS - 4 pi u(x0) on the
  /// target's own cell (the form the solver uses).
  Subtracted,
  /// The principal value integrated as it stands, by the polar rules on the elements
  /// that hold the target (used to check the identities).
  Direct,
};

} // namespace capsula::operators
