// A failed run's reason shortened for a table cell: the solver's flag, the collapse time, or
// the message's first clause cut between words, never inside one.
#include <gtest/gtest.h>

#include <string>

#include "studies/contract/FailureReason.hpp"

using granwave::shortReason;

TEST(FailureReason, ShortReasonNamesTheSolverFlagOrTheCollapseTime) {
  EXPECT_EQ(shortReason("hydrodynamic solver: CVode failed: CV_CONV_FAILURE (-4) at t = 0.12 s"),
            "CV_CONV_FAILURE");
  EXPECT_EQ(shortReason("inelastic collapse at t = 0.047710366 s: particle 194 collided"),
            "collapse at t = 0.048 s");
}

TEST(FailureReason, ShortReasonKeepsTheFirstClauseWhole) {
  EXPECT_EQ(shortReason("no steady cycles were pooled: the run is too short or never became "
                        "steady (run longer, or give the number of cycles to discard)"),
            "no steady cycles were pooled: the run is too short or never became steady");
}

TEST(FailureReason, ShortReasonCutsALongClauseBetweenWordsAndMarksTheCut) {
  std::string message;
  for (int i = 0; i < 30; ++i) message += "word" + std::to_string(i) + " ";
  const std::string s = shortReason(message);
  ASSERT_LE(s.size(), 80u + 4u);  // " …" is 4 bytes in UTF-8
  EXPECT_EQ(s.substr(s.size() - 4), " …");
  const std::string kept = s.substr(0, s.size() - 4);
  EXPECT_EQ(message.compare(0, kept.size(), kept), 0);
  EXPECT_EQ(message[kept.size()], ' ');  // cut at a space: the last word kept whole
}
