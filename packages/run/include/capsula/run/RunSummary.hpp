#pragma once
// summary.json, one layout for every app (keys in this order):
//
//   application, status       "running", "finished", "steady", "too close", "failed",
//                              "interrupted" (SIGTERM or SIGINT: InterruptionWatch.hpp)
//   failure | stop reason      why a failed run failed, why a run stopped early
//   time                       where the run is (in the app's time: t, or tau for tether2d)
//   version                    {capsula, git sha, trilinos}
//   ranks, restarted
//   terms                      the physics and output terms built (the model names them)
//   steps                      the integration statistics (statisticsJson)
//   ...                        the app's results (final values, extremes, ...)
//   timings                    {wall seconds (this process), seconds per rhs evaluation
//                              (this process), then every timer that ran, by the name its
//                              owner gave it (core::timerTotals)}
//   peak memory (MiB) per rank the peak resident memory of every rank, as last recorded
//                              (recordPeakMemory; absent before)
//   deck                       the validated deck (XML)
#include <capsula/io/Json.hpp>
#include <capsula/timeint/IntegrationState.hpp>

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>

#include <chrono>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace capsula::run {

/// The integration statistics as summary.json's "steps": accepted, rejected, rhs
/// evaluations, smallest, largest, and where a stiff method ran its steps, linear solves
/// and Krylov iterations. The one place that knows their names.
io::JsonValue statisticsJson(const timeint::IntegrationStatistics& statistics);

class RunSummary {
public:
  RunSummary(std::string application, const Teuchos::ParameterList& validatedDeck, int ranks);

  /// This process's part of the run starts now, with `statistics` done before it (a restart
  /// continues them): the wall clock and the rate per right-hand side count from here.
  void begin(const timeint::IntegrationStatistics& statistics, bool restarted);
  void setTerms(std::vector<std::string> terms) { terms_ = std::move(terms); }
  const std::vector<std::string>& terms() const { return terms_; }
  /// The log's account of what the run built: "Terms built:" and a line per term.
  void printTerms(std::ostream& log) const;
  /// Wall seconds since begin().
  double wallSeconds() const;
  /// Gathers every rank's peak resident memory for the next documents: collective, so the
  /// runs call it where every rank is (the summaries themselves are made on rank 0 only).
  void recordPeakMemory(const Teuchos::Comm<int>& comm);
  const std::vector<double>& peakMemoryMiB() const { return peakMemoryMiB_; }

  /// The document: `note` is the failure (status "failed") or why the run stopped early (""
  /// for none); `results` adds the app's entries after "steps".
  io::JsonValue json(const std::string& status, const std::string& note, double time,
                     const timeint::IntegrationStatistics& statistics,
                     const std::function<void(io::JsonValue&)>& results) const;

private:
  std::string application_;
  std::string deckXml_;
  int ranks_;
  bool restarted_ = false;
  std::vector<std::string> terms_;
  std::chrono::steady_clock::time_point wallStart_ = std::chrono::steady_clock::now();
  std::int64_t evaluationsAtStart_ = 0;
  std::vector<double> peakMemoryMiB_;
};

} // namespace capsula::run
