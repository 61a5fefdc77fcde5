#pragma once
// A study: a plan of runs (particles and hydro), then an analysis of their outputs into
// numbers (results.h5 /results) and a report. One implementation per study kind
// (docs/studies.md): wave-fronts, sound-speed, effective-restitution, momentum-transfer.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "h5/File.hpp"
#include "studies/contract/StudyFile.hpp"
#include "studies/report/Report.hpp"
#include "studies/runner/RunRequest.hpp"

namespace granwave {

// The finished runs of a study, by label.
class RunSet {
 public:
  explicit RunSet(std::vector<RunRecord> records);
  const RunRecord& get(const std::string& label) const;  // throws if never planned
  bool has(const std::string& label) const { return index_.count(label) > 0; }
  const std::vector<RunRecord>& all() const { return records_; }

 private:
  std::vector<RunRecord> records_;
  std::map<std::string, std::size_t> index_;
};

// A round of runs a study adds once the earlier ones are known, with why, and the most that
// may still follow it, so that the progress can say both.
struct FollowUp {
  std::vector<RunRequest> runs;  // empty: nothing more is needed
  std::string reason;            // "the dry law's simplest-model verdict is undecided over 5 seeds"
  int rounds_after = 0;          // rounds that may follow this one, at most
  std::size_t runs_after = 0;    // runs those rounds may add, at most
};

class Study {
 public:
  virtual ~Study() = default;
  virtual std::string title() const = 0;
  virtual std::vector<RunRequest> plan() const = 0;
  // The runs to add once `runs` (the plan and every earlier follow-up, finished) are known: a
  // study whose verdict is not yet decided asks for more seeds here, up to its cap. No runs
  // when nothing more is needed; the default asks for nothing.
  virtual FollowUp followUp(const RunSet& /*runs*/) const { return {}; }
  // Writes the measured numbers under /results of `results` and fills `report`.
  virtual void analyse(const RunSet& runs, h5::File& results, Report& report) const = 0;
};

}  // namespace granwave
