// Sweeps: the factor lists, the cells as Monte Carlos of the scaled configuration, and shards.

#include <gtest/gtest.h>

#include <cmath>

#include "analysis_test_support.hpp"
#include "legofeup/lessons/analysis/monte_carlo.hpp"
#include "legofeup/lessons/analysis/sweep.hpp"
#include "legofeup/lessons/input_error.hpp"

namespace legofeup::lessons::analysis {
namespace {

using testing::short_run_config;

TEST(SweepScales, ListsAndLogRanges) {
    EXPECT_EQ(parse_scales("0.01,0.1,1,10", "--q"), (std::vector<double>{0.01, 0.1, 1.0, 10.0}));
    EXPECT_EQ(parse_scales("3", "--q"), (std::vector<double>{3.0}));
    const std::vector<double> range = parse_scales("1e-2:1e2:5", "--r");
    ASSERT_EQ(range.size(), 5U);
    const double expected[] = {0.01, 0.1, 1.0, 10.0, 100.0};
    for (std::size_t k = 0; k < 5; ++k) {
        EXPECT_NEAR(range[k], expected[k], 1e-12 * expected[k]) << k;
    }
    EXPECT_EQ(range.front(), 0.01);  // the ends exactly as written
    EXPECT_EQ(range.back(), 100.0);
    const std::vector<double> three = parse_scales("1:4:3", "--r");
    EXPECT_NEAR(three[1], 2.0, 1e-12);  // the geometric middle
}

TEST(SweepScales, RejectsBadListsNamingTheOptionAndTheValue) {
    for (const char* text : {"", "a", "1,,2", "0", "-1", "1,inf", "1:2", "1:10:1", "1:10:x",
                             "1:10:2.5", "0:10:3", "1:2:3:4"}) {
        try {
            parse_scales(text, "--q");
            ADD_FAILURE() << text;
        } catch (const InputError& error) {
            ASSERT_EQ(error.problems().size(), 1U) << text;
            EXPECT_EQ(error.problems()[0].key, "--q") << text;
            EXPECT_EQ(error.problems()[0].value, text);
            EXPECT_FALSE(error.problems()[0].reason.empty());
        }
    }
}

TEST(Sweep, EachCellIsTheMonteCarloOfItsScaledConfiguration) {
    SweepSpec spec{short_run_config(), {1.0, 100.0}, {0.1}, 2, 3};
    const std::vector<SweepCell> cells = run_sweep(spec, 2);
    ASSERT_EQ(cells.size(), 2U);
    for (std::size_t k = 0; k < cells.size(); ++k) {
        const SweepCell& cell = cells[k];
        EXPECT_EQ(cell.index, k);
        EXPECT_EQ(cell.q_index, k);
        EXPECT_EQ(cell.r_index, 0U);
        EXPECT_EQ(cell.runs, 2U);
        MonteCarloSpec alone{spec.config, spec.runs, spec.first_seed};
        alone.config.filter.q11 *= spec.q_scales[k];
        alone.config.filter.q22 *= spec.q_scales[k];
        alone.config.filter.r11 *= 0.1;
        alone.config.filter.r22 *= 0.1;
        const MonteCarloSummary summary =
            summarize(run_monte_carlo(alone, 1), spec.config.simulator.control_period);
        EXPECT_EQ(cell.mean_nees, summary.mean_nees) << k;
        EXPECT_EQ(cell.rms_position_error, summary.rms_position_error.mean) << k;
        EXPECT_EQ(cell.nees_inside_fraction, summary.nees_inside_fraction) << k;
        EXPECT_DOUBLE_EQ(cell.consistency, std::log10(summary.mean_nees / 3.0)) << k;
    }
    // A hundred times the process noise makes P larger: the NEES falls.
    EXPECT_LT(cells[1].mean_nees, cells[0].mean_nees);
}

TEST(Sweep, ShardsSplitTheCellsAndTogetherGiveTheWhole) {
    SweepSpec spec{short_run_config(3.0), {0.1, 10.0}, {1.0, 10.0}, 1, 1};
    const std::vector<SweepCell> whole = run_sweep(spec, 2);
    ASSERT_EQ(whole.size(), 4U);
    const std::vector<SweepCell> first = run_sweep(spec, 1, {1, 2});
    const std::vector<SweepCell> second = run_sweep(spec, 1, {2, 2});
    ASSERT_EQ(first.size(), 2U);
    ASSERT_EQ(second.size(), 2U);
    EXPECT_EQ(first[0].index, 0U);
    EXPECT_EQ(first[1].index, 2U);
    EXPECT_EQ(second[0].index, 1U);
    EXPECT_EQ(second[1].index, 3U);
    for (const SweepCell& part : {first[0], first[1], second[0], second[1]}) {
        EXPECT_EQ(part.mean_nees, whole[part.index].mean_nees);
        EXPECT_EQ(part.rms_position_error, whole[part.index].rms_position_error);
        EXPECT_EQ(part.q_scale, spec.q_scales[part.index / 2]);
        EXPECT_EQ(part.r_scale, spec.r_scales[part.index % 2]);
    }
}

}  // namespace
}  // namespace legofeup::lessons::analysis
