#include "capsula/run/RunSummary.hpp"

#include <capsula/core/Deck.hpp>
#include <capsula/core/PeakMemory.hpp>
#include <capsula/core/RunInfo.hpp>
#include <capsula/core/Timers.hpp>

#include <algorithm>
#include <ostream>

namespace capsula::run {

io::JsonValue statisticsJson(const timeint::IntegrationStatistics& statistics)
{
  io::JsonValue steps = io::JsonValue::object();
  steps["accepted"] = static_cast<long long>(statistics.acceptedSteps);
  steps["rejected"] = static_cast<long long>(statistics.rejectedSteps);
  steps["rejected outside the model"] = static_cast<long long>(statistics.rejectedOutsideDomain);
  steps["rhs evaluations"] = static_cast<long long>(statistics.rhsEvaluations);
  steps["smallest"] = statistics.smallestStep;
  steps["largest"] = statistics.largestStep;
  if (statistics.stiffSteps > 0 || statistics.methodSwitches > 0 || statistics.linearisations > 0) {
    // The stiff methods (docs/stiff-integration.md): their steps and linear solves.
    steps["stiff steps"] = static_cast<long long>(statistics.stiffSteps);
    steps["rhs evaluations in stiff steps"] = static_cast<long long>(statistics.stiffRhsEvaluations);
    steps["linearisations"] = static_cast<long long>(statistics.linearisations);
    steps["linear solves"] = static_cast<long long>(statistics.linearSolves);
    steps["linear iterations"] = static_cast<long long>(statistics.linearIterations);
    steps["linear iterations per stiff step"] =
        statistics.stiffSteps > 0
            ? static_cast<double>(statistics.linearIterations) / static_cast<double>(statistics.stiffSteps)
            : 0.0;
    steps["largest linear iterations"] = static_cast<long long>(statistics.largestLinearIterations);
    steps["failed linear solves"] = static_cast<long long>(statistics.failedLinearSolves);
    steps["method switches"] = static_cast<long long>(statistics.methodSwitches);
  }
  return steps;
}

RunSummary::RunSummary(std::string application, const Teuchos::ParameterList& validatedDeck, int ranks)
    : application_(std::move(application)), deckXml_(core::deckToXml(validatedDeck, false)), ranks_(ranks)
{}

void RunSummary::begin(const timeint::IntegrationStatistics& statistics, bool restarted)
{
  wallStart_ = std::chrono::steady_clock::now();
  evaluationsAtStart_ = statistics.rhsEvaluations;
  restarted_ = restarted;
}

void RunSummary::printTerms(std::ostream& log) const
{
  log << "Terms built:\n";
  for (const auto& term : terms_) {
    log << "  " << term << "\n";
  }
}

double RunSummary::wallSeconds() const
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart_).count();
}

void RunSummary::recordPeakMemory(const Teuchos::Comm<int>& comm)
{
  peakMemoryMiB_ = core::peakResidentMiBPerRank(comm);
}

io::JsonValue RunSummary::json(const std::string& status, const std::string& note, double time,
                               const timeint::IntegrationStatistics& statistics,
                               const std::function<void(io::JsonValue&)>& results) const
{
  io::JsonValue summary = io::JsonValue::object();
  summary["application"] = application_;
  summary["status"] = status;
  if (!note.empty()) {
    summary[status == "failed" ? "failure" : "stop reason"] = note;
  }
  summary["time"] = time;
  summary["version"]["capsula"] = core::capsulaVersion();
  summary["version"]["git sha"] = core::gitSha();
  summary["version"]["trilinos"] = core::trilinosVersion();
  summary["ranks"] = ranks_;
  summary["restarted"] = restarted_;
  summary["terms"] = io::JsonValue::array();
  for (const auto& term : terms_) {
    summary["terms"].append(term);
  }
  summary["steps"] = statisticsJson(statistics);
  if (results) {
    results(summary);
  }
  const double wall = wallSeconds();
  const std::int64_t evaluations = statistics.rhsEvaluations - evaluationsAtStart_;
  summary["timings"]["wall seconds (this process)"] = wall;
  summary["timings"]["seconds per rhs evaluation (this process)"] =
      wall / static_cast<double>(std::max<std::int64_t>(1, evaluations));
  for (const auto& timer : core::timerTotals()) {
    summary["timings"][timer.name] = timer.seconds;
  }
  if (!peakMemoryMiB_.empty()) {
    summary["peak memory (MiB) per rank"] = io::JsonValue::array(peakMemoryMiB_);
  }
  summary["deck"] = deckXml_;
  return summary;
}

} // namespace capsula::run
