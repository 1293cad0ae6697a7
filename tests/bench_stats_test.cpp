// The bench command's statistics: nearest-rank percentiles and the per-frame budget rule.
#include "../app/bench_command.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace gbl;

TEST(BenchStats, NearestRankPercentiles) {
    // 20 samples 1..20 in scrambled order: the median is the 10th (lower median), p95 the 19th.
    std::vector<double> v;
    for (int i = 0; i < 20; ++i) v.push_back(double((i * 7) % 20 + 1));
    EXPECT_EQ(percentile(v, 0.5), 10.0);
    EXPECT_EQ(percentile(v, 0.95), 19.0);
    EXPECT_EQ(percentile(v, 1.0), 20.0);
    // Odd count: the true median.
    EXPECT_EQ(percentile({5.0, 1.0, 3.0}, 0.5), 3.0);
    // One sample is every percentile; none is NaN.
    EXPECT_EQ(percentile({4.5}, 0.95), 4.5);
    EXPECT_TRUE(std::isnan(percentile({}, 0.5)));
    // A single outlier among 20 does not move p95 but a second one does.
    std::vector<double> w(20, 1.0);
    w[3] = 100.0;
    EXPECT_EQ(percentile(w, 0.95), 1.0);
    w[7] = 90.0;
    EXPECT_EQ(percentile(w, 0.95), 90.0);
}

TEST(BenchStats, NextFrameMustFitTheBudget) {
    EXPECT_TRUE(frameFitsBudget(10.0, 5.0, 60.0));
    EXPECT_TRUE(frameFitsBudget(55.0, 5.0, 60.0));
    EXPECT_FALSE(frameFitsBudget(55.1, 5.0, 60.0));
    EXPECT_FALSE(frameFitsBudget(0.0, 61.0, 60.0));
}

TEST(BenchStats, PerPairCostAndWorkFloor) {
    // Quad: 1000 ms for 100M evaluated pairs = 10 ns per pair.
    PairCost const q = pairCost({1000.0, 100'000'000, 20'000'000}, std::nan(""));
    EXPECT_DOUBLE_EQ(q.nsPerEvaluated, 10.0);
    EXPECT_DOUBLE_EQ(q.evaluatedPerLit, 5.0);
    EXPECT_TRUE(std::isnan(q.floorMs));  // no quad figure given
    // Volumes: 25M evaluated for 20M lit in 750 ms = 30 ns per pair, 3x quad's; the floor is
    // 20M lit pairs x 10 ns = 200 ms, and 750 ms is 3.75x that.
    PairCost const v = pairCost({750.0, 25'000'000, 20'000'000}, 10.0);
    EXPECT_DOUBLE_EQ(v.nsPerEvaluated, 30.0);
    EXPECT_DOUBLE_EQ(v.evaluatedPerLit, 1.25);
    EXPECT_DOUBLE_EQ(v.perPairVsQuad, 3.0);
    EXPECT_DOUBLE_EQ(v.floorMs, 200.0);
    EXPECT_DOUBLE_EQ(v.vsFloor, 3.75);
    // The two factors multiply to the distance from the floor.
    EXPECT_DOUBLE_EQ(v.evaluatedPerLit * v.perPairVsQuad, v.vsFloor);
    EXPECT_EQ(pairVerdict("volumes", v),
              "volumes: 1.25\u00d7 the ideal number of light\u00b7pixel evaluations, 3.00\u00d7 the per-pair cost of "
              "quad, 3.75\u00d7 the work floor (200.0 ms)");
    // Nothing lit: no ratio is made up.
    PairCost const none = pairCost({5.0, 1000, 0}, 10.0);
    EXPECT_TRUE(std::isnan(none.evaluatedPerLit));
    EXPECT_TRUE(std::isnan(none.vsFloor));
    EXPECT_EQ(pairVerdict("tiled", none), "tiled: no light reached a surface, nothing to compare");
}
