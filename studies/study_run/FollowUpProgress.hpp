#pragma once
// What `granwave study` says before a follow-up round (more seeds for an undecided verdict):
// which round, how many runs and why, how many more rounds and runs may follow at most, and
// the wall time of this round and of all that may follow, at the pace of the runs made so far.
#include <string>

#include "studies/contract/Study.hpp"

namespace granwave {

// Wall seconds a run like `request` takes, from the finished runs of the same kind, scene
// size and simulated duration (else of the same kind); 0 if none is known.
double expectedWall(const RunRequest& request, const RunSet& done);

// One line (without the "granwave study: " prefix). `round` counts the plan as round 1.
std::string followUpLine(int round, const FollowUp& more, const RunSet& done, int jobs);

}  // namespace granwave
