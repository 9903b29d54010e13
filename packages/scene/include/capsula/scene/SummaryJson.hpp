#pragma once
// The per-cell and per-pair objects of summary.json (SceneRun.hpp): the same quantities as
// the metrics.csv columns, named in words.
#include "capsula/scene/OutputMetrics.hpp"
#include "capsula/scene/PairMetrics.hpp"

#include <capsula/io/Json.hpp>
#include <capsula/timeint/IntegrationState.hpp>

namespace capsula::scene {

/// One cell's sample; the wall gap only with a wall (`wall`), where it means something.
io::JsonValue sampleJson(const CellSample& s, bool wall);

/// One pair of cells' sample.
io::JsonValue pairJson(const PairSample& p);

/// The integrator's counters ("steps" of summary.json); those of the stiff methods only
/// where a stiff step was taken or the method switched.
io::JsonValue integrationStatisticsJson(const timeint::IntegrationStatistics& s);

} // namespace capsula::scene
