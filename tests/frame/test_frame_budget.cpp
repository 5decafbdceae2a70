// The one-budget rule (core/budget.h) on made-up fronts: the lowest summed error within the budget,
// its ties, nothing fitting, and an independent exhaustive search over random fronts.
#include "core/budget.h"

#include <gtest/gtest.h>

#include <functional>
#include <random>

using postfx::core::BudgetSolution;
using postfx::core::chooseWithinBudget;
using postfx::core::PresetFront;

namespace {

// Two made-up effects: A's presets 0.1 / 0.2 / 0.4 / 0.8 ms, B's 0.15 / 0.3 / 0.6 ms.
const PresetFront kA{{0.1, 0.2, 0.4, 0.8}, {0.05, 0.02, 0.01, 0.005}};
const PresetFront kB{{0.15, 0.3, 0.6}, {0.04, 0.015, 0.01}};

}  // namespace

TEST(FrameBudget, LowestSummedErrorWithinTheBudget) {
    // Within 0.6 ms: (A1, B1) 0.5 ms, error 0.035 beats (A2, B0) 0.55 ms, 0.05 and (A1, B0) 0.35, 0.06.
    const BudgetSolution s = chooseWithinBudget({kA, kB}, 0.6);
    EXPECT_TRUE(s.fits);
    EXPECT_EQ(s.presets, (std::vector<uint32_t>{1, 1}));
    EXPECT_NEAR(s.ms, 0.5, 1e-12);
    EXPECT_NEAR(s.error, 0.035, 1e-12);
    // Within 0.9 ms: (A2, B1) 0.7 ms 0.025 beats (A1, B2) 0.8 ms 0.03; within 1.05 ms, (A2, B2) 1.0 ms 0.02.
    EXPECT_EQ(chooseWithinBudget({kA, kB}, 0.9).presets, (std::vector<uint32_t>{2, 1}));
    EXPECT_EQ(chooseWithinBudget({kA, kB}, 1.05).presets, (std::vector<uint32_t>{2, 2}));
    // Within 1.45 ms: everything's highest (1.4 ms).
    const BudgetSolution all = chooseWithinBudget({kA, kB}, 1.45);
    EXPECT_EQ(all.presets, (std::vector<uint32_t>{3, 2}));
    EXPECT_TRUE(all.fits);
}

TEST(FrameBudget, NothingFitsGivesEachEffectsFastestPreset) {
    const BudgetSolution s = chooseWithinBudget({kA, kB}, 0.2);
    EXPECT_FALSE(s.fits);
    EXPECT_EQ(s.presets, (std::vector<uint32_t>{0, 0}));
    EXPECT_NEAR(s.ms, 0.25, 1e-12);
    // A front whose fastest preset is not its first (a measurement on a device where Low is slower).
    const PresetFront odd{{0.3, 0.2, 0.5}, {0.03, 0.02, 0.01}};
    EXPECT_EQ(chooseWithinBudget({odd}, 0.1).presets, (std::vector<uint32_t>{1}));
}

TEST(FrameBudget, AHigherPresetWithMoreErrorIsNotChosen) {
    // Made-up front where preset 2 costs more than preset 1 and is less accurate (noise in a front).
    const PresetFront bumpy{{0.1, 0.3, 0.5, 0.9}, {0.05, 0.01, 0.012, 0.004}};
    EXPECT_EQ(chooseWithinBudget({bumpy}, 0.6).presets, (std::vector<uint32_t>{1}));
    EXPECT_EQ(chooseWithinBudget({bumpy}, 0.9).presets, (std::vector<uint32_t>{3}));
}

TEST(FrameBudget, TiesGoToTheLowerTimeThenTheLowerPresets) {
    // Same error, different time: the faster.
    const PresetFront flat{{0.1, 0.2, 0.3}, {0.02, 0.01, 0.01}};
    EXPECT_EQ(chooseWithinBudget({flat}, 1.0).presets, (std::vector<uint32_t>{1}));
    // Same error and time: the lower presets of the first effect.
    const PresetFront x{{0.1, 0.2}, {0.02, 0.01}};
    const PresetFront y{{0.1, 0.2}, {0.02, 0.01}};
    EXPECT_EQ(chooseWithinBudget({x, y}, 0.35).presets, (std::vector<uint32_t>{0, 1}));
}

TEST(FrameBudget, NoEffectsAndEmptyFronts) {
    const BudgetSolution none = chooseWithinBudget({}, 1.0);
    EXPECT_TRUE(none.fits);
    EXPECT_TRUE(none.presets.empty());
    // An effect without presets takes no part: the other is chosen as alone.
    const BudgetSolution s = chooseWithinBudget({PresetFront{}, kB}, 0.4);
    EXPECT_EQ(s.presets, (std::vector<uint32_t>{0, 1}));
    EXPECT_NEAR(s.ms, 0.3, 1e-12);
}

TEST(FrameBudget, MatchesAnExhaustiveSearchOnRandomFronts) {
    std::mt19937 rng(20261127);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int round = 0; round < 300; ++round) {
        std::vector<PresetFront> fronts(1 + rng() % 4);
        for (PresetFront& f : fronts) {
            const size_t n = 1 + rng() % 5;
            for (size_t p = 0; p < n; ++p) {
                f.ms.push_back(0.05 + unit(rng));
                f.error.push_back(0.001 + 0.1 * unit(rng));
            }
        }
        const double budget = 3.0 * unit(rng);
        // Recursive search for the lowest error within the budget (errors are distinct almost surely).
        double bestError = 1e300;
        std::vector<uint32_t> at(fronts.size()), best;
        std::function<void(size_t, double, double)> search = [&](size_t f, double ms, double error) {
            if (f == fronts.size()) {
                if (ms <= budget && error < bestError) bestError = error, best = at;
                return;
            }
            for (uint32_t p = 0; p < fronts[f].ms.size(); ++p) {
                at[f] = p;
                search(f + 1, ms + fronts[f].ms[p], error + fronts[f].error[p]);
            }
        };
        search(0, 0.0, 0.0);
        const BudgetSolution s = chooseWithinBudget(fronts, budget);
        if (best.empty()) {
            EXPECT_FALSE(s.fits) << "round " << round;
            continue;
        }
        EXPECT_TRUE(s.fits) << "round " << round;
        EXPECT_EQ(s.presets, best) << "round " << round;
        EXPECT_NEAR(s.error, bestError, 1e-12) << "round " << round;
        EXPECT_LE(s.ms, budget) << "round " << round;
    }
}
