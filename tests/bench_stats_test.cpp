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
