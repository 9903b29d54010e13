#pragma once
// The back-end interface of the regular (far-field) quadrature sums of eq 3.39: the layer
// potentials (LayerPotentials.hpp) hand their sources and targets to a FarFieldSummation
// and add the exact singular and near-singular corrections to what it returns, so a fast
// back-end approximates only the regular rule, never the special ones.
//
// DirectSummation (DirectSummation.hpp) runs the vectorised loops of RegularSums.hpp over
// every point, as the layer potentials always did (bit-identical results). A fast back-end
// (a treecode, capsula::fastsum) registers a factory under its deck name
// (FarFieldRegistry.hpp, 'Operator/Summation').
//
// Sources: all quadrature points of all cells, cell c being the contiguous range
// [cellPointOffsets[c], cellPointOffsets[c + 1]). Targets: n points, 3 coordinates each.
#include <capsula/operators/RegularSums.hpp>

#include <string>
#include <vector>

namespace capsula::operators {

class FarFieldSummation {
public:
  virtual ~FarFieldSummation() = default;

  /// The deck name of the back-end ('Operator/Summation').
  virtual std::string name() const = 0;

  /// New source positions (the geometry changed); the pointers stay valid until the next
  /// call. cellPointOffsets has numCells + 1 entries.
  virtual void setSources(const double* x, const double* y, const double* z,
                          const std::vector<int>& cellPointOffsets) = 0;

  /// result[3 t + j] = sum_q G_ij(x_q, x_t) f_q,i over every source (the positions of
  /// `sources` are those of setSources).
  virtual void singleLayer(const SingleLayerSources& sources, const double* targets, int n, double* result) = 0;

  /// result[3 t + j] = sum_q T_ijk(x_q, x_t) (v_q - s_t)_i a_q,k, where s_t =
  /// subtracted[3 t ..] for the sources of cell targetCells[t] (the singularity subtraction
  /// of eq 3.44 on a target's own cell) and 0 elsewhere. targetCells == nullptr: no
  /// subtraction (subtracted unused). Consecutive targets of one cell are expected in
  /// node order (the direct sums block them as the layer potentials did).
  virtual void doubleLayer(const DoubleLayerSources& sources, const double* targets, const int* targetCells,
                           const double* subtracted, int n, double* result) = 0;
};

} // namespace capsula::operators
