#include "core/budget.h"

#include <algorithm>
#include <cstddef>

namespace postfx::core {

BudgetSolution chooseWithinBudget(const std::vector<PresetFront>& fronts, double budgetMs) {
    const size_t n = fronts.size();
    auto count = [&](size_t f) { return std::min(fronts[f].ms.size(), fronts[f].error.size()); };

    BudgetSolution best;
    best.presets.assign(n, 0);
    bool found = false;
    // Every combination in lexicographic order (the first front's preset changing slowest), so that a
    // later combination with equal error and time never replaces an earlier (lower) one.
    std::vector<uint32_t> at(n, 0);
    while (true) {
        double ms = 0.0, error = 0.0;
        for (size_t f = 0; f < n; ++f) {
            if (count(f) == 0) continue;
            ms += fronts[f].ms[at[f]];
            error += fronts[f].error[at[f]];
        }
        if (ms <= budgetMs && (!found || error < best.error || (error == best.error && ms < best.ms))) {
            found = true;
            best.presets = at;
            best.ms = ms;
            best.error = error;
        }
        bool advanced = false;
        for (size_t f = n; f-- > 0;) {
            if (count(f) > 0 && at[f] + 1 < count(f)) {
                ++at[f];
                advanced = true;
                break;
            }
            at[f] = 0;
        }
        if (!advanced) break;
    }
    if (found) {
        best.fits = true;
        return best;
    }
    // Nothing fits: the fastest of each.
    best = {};
    best.presets.assign(n, 0);
    for (size_t f = 0; f < n; ++f) {
        if (count(f) == 0) continue;
        uint32_t fastest = 0;
        for (uint32_t p = 1; p < count(f); ++p)
            if (fronts[f].ms[p] < fronts[f].ms[fastest]) fastest = p;
        best.presets[f] = fastest;
        best.ms += fronts[f].ms[fastest];
        best.error += fronts[f].error[fastest];
    }
    best.fits = false;
    return best;
}

}  // namespace postfx::core
