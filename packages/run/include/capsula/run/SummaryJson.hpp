#pragma once
// The per-cell and per-pair objects of summary.json (SceneRun.hpp): the same quantities as
// the metrics.csv columns, named in words.
#include "capsula/run/OutputMetrics.hpp"
#include "capsula/run/PairMetrics.hpp"

#include <capsula/io/Json.hpp>

namespace capsula::run {

/// One cell's sample; the wall gap only with a wall (`wall`), where it means something.
io::JsonValue sampleJson(const CellSample& s, bool wall);

/// One pair of cells' sample.
io::JsonValue pairJson(const PairSample& p);

} // namespace capsula::run
