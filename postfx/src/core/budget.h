// One GPU time budget for all of postfx's work (FrameInfo::budgetMs; docs/architecture.md, "One budget
// for the frame"): the choice of one preset per effect that gives the lowest total error within it.
#pragma once

#include <cstdint>
#include <vector>

namespace postfx::core {

// One effect's accuracy–cost front: per preset (lowest first), its measured GPU time on this device
// [ms] and its error (relative RMSE against the effect's double reference, from the committed
// accuracy–cost fronts; a fraction, 0.01 = 1%).
struct PresetFront {
    std::vector<double> ms;
    std::vector<double> error;
};

struct BudgetSolution {
    std::vector<uint32_t> presets;  // one per front
    double ms = 0.0;                // Σ the chosen presets' times
    double error = 0.0;             // Σ their errors
    bool fits = false;              // ms <= the budget given to chooseWithinBudget
};

// The rule: among every combination of one preset per front whose summed time is within `budgetMs`,
// the one with the lowest summed error; ties go to the lower summed time, then to the lower presets
// (the first front's first). When none fits: each front's fastest preset (fits = false). Exhaustive
// over the combinations (postfx has at most a few effects with at most kMaxPresets presets each).
// Fronts with no presets are skipped (their entry in `presets` is 0).
BudgetSolution chooseWithinBudget(const std::vector<PresetFront>& fronts, double budgetMs);

}  // namespace postfx::core
