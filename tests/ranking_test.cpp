/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// rankPositions(): the ranks of `topoeval rank`, Python rank() and the batch (paper Table I).

#include <gtest/gtest.h>
#include <mrpt_topoeval/scores/ranking.h>

#include <cmath>
#include <string>
#include <vector>

using mrpt_topoeval::rankPositions;

TEST(Ranking, HigherFirstTiesShareInvalidEmpty)
{
    // Ranks constructed first: 0.9 best, 0.5 and 0.5004 equal to 3 decimals share "2-3".
    const std::vector<std::string> expected = {"4", "1", "", "2-3", "2-3"};
    EXPECT_EQ(rankPositions({0.1, 0.9, 0.95, 0.5, 0.5004}, {true, true, false, true, true}),
              expected);
}

TEST(Ranking, NotFiniteRanksLastAndNothingValidGivesNoRank)
{
    const std::vector<std::string> last = {"2", "1"};
    EXPECT_EQ(rankPositions({std::nan(""), 0.0}, {true, true}), last);
    const std::vector<std::string> none = {"", ""};
    EXPECT_EQ(rankPositions({1.0, 2.0}, {false, false}), none);
    EXPECT_TRUE(rankPositions({}, {}).empty());
}
