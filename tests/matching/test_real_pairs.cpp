// The graph matcher on real pairs: 40 relations of the mit-csail benchmark log, evenly spaced,
// matched without a guess (split-merge segments). On all 1172 relations the matcher succeeds
// on ~93 % and gives a confident wrong pose on ~2.4 % (README, B2), so 40 pairs must give
// >= 80 % successes (> 3 sigma of binomial noise below) and at most 3 confident wrong poses.
#include <gtest/gtest.h>
#include <toposlam/matchingbench/MatchingBenchmark.h>
#include <toposlam/matchingbench/RelationPairs.h>

#include <TestSupport.h>

using namespace toposlam;

TEST(GraphMatcherOnRealData, MitCsailRelationPairsWithoutGuess) {
    TOPOSLAM_SHARED_DATA_OR_SKIP(log, "slam/mit-csail.clf");
    TOPOSLAM_SHARED_DATA_OR_SKIP(relations, "slam/mit-csail.relations");
    const matchingbench::ScanPairs pairs =
        matchingbench::loadRelationPairs(log, relations, "mit-csail", 40);
    ASSERT_EQ(pairs.size(), 40u);
    matchingbench::GraphPairMatcher graph("graph", "split-merge", matching::GraphMatcherOptions());
    std::size_t successes = 0, wrong = 0;
    for (const matchingbench::ScanPair& p : pairs) {
        const matchingbench::PairOutcome o = graph.match(p, std::nullopt);
        const bool ok = matchingbench::isSuccess(o.pose, p.truth);
        successes += o.answered && ok;
        wrong += o.answered && !ok;
    }
    EXPECT_GE(successes, 32u);
    EXPECT_LE(wrong, 3u);
}
