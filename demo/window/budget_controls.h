// The windowed demo's "Frame budget" section of the ImGui panel: one GPU time budget for all of postfx's
// work (Scene::budgetMs, FrameInfo::budgetMs). Turning it on puts every enabled effect with presets (the
// ray-marched fog, the clouds) on quality Auto, which the budget then chooses for; the section shows what
// it chose (Context::budgetChoice), the overlay too (budgetChoiceLines).
#pragma once

#include "scene/scene.h"

#include <postfx/context.h>

#include <string>
#include <vector>

namespace demo::window {

class BudgetControls {
public:
    // Adds the section to the current ImGui window (call between Begin and End), editing scene.budgetMs
    // and the effects' quality; `context` is asked for the last frame's choice. Returns true if anything
    // changed this frame.
    bool build(Scene& scene, const postfx::Context& context);

private:
    float lastBudgetMs_ = 1.0f;  // the slider's value while the budget is off
};

// The budget's choice for the last recorded frame as text lines: "budget 1 ms: ..." and one line per
// effect on Auto ("clouds medium 0.49 ms, error 0.98%"); "measuring the presets" while they are
// measured; empty when the scene has no budget.
std::vector<std::string> budgetChoiceLines(const Scene& scene, const postfx::Context& context);

}  // namespace demo::window
