#include "window/budget_controls.h"

#include "window/medium_controls.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace demo::window {
namespace {

using widgets::tooltip;

constexpr float kMinBudgetMs = 0.05f, kMaxBudgetMs = 20.0f;  // the slider's range [ms]
constexpr const char* kPresetNames[] = {"low", "medium", "high", "ultra"};

std::string format(const char* fmt, double a, double b = 0.0, double c = 0.0) {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, fmt, a, b, c);
    return buffer;
}

}  // namespace

std::vector<std::string> budgetChoiceLines(const Scene& scene, const postfx::Context& context) {
    if (!(scene.budgetMs > 0.0f)) return {};
    postfx::BudgetChoice choice;
    const postfx::Status s = context.budgetChoice(choice);
    if (!s.ok()) return {format("budget %.3g ms: measuring the presets", scene.budgetMs)};
    std::vector<std::string> lines;
    lines.push_back(format("budget %.3g ms: other work %.3f ms + chosen %.3f ms", choice.budgetMs,
                           choice.otherMs, choice.chosenMs) +
                    (choice.fits ? "" : " (over: lowest presets)"));
    for (const postfx::BudgetChoice::EffectChoice& e : choice.effects) {
        const char* preset = e.preset < std::size(kPresetNames) ? kPresetNames[e.preset] : "?";
        lines.push_back("  " + e.effect + " " + preset +
                        format(": %.3f ms, error %.2f%%", e.ms, 100.0 * e.error));
    }
    if (choice.effects.empty()) lines.push_back("  no effect on quality auto");
    return lines;
}

bool BudgetControls::build(Scene& scene, const postfx::Context& context) {
    if (!ImGui::CollapsingHeader("Frame budget")) return false;
    bool on = scene.budgetMs > 0.0f;
    bool changed = false;
    if (ImGui::Checkbox("one budget for postfx", &on)) {
        changed = true;
        if (on) {
            scene.budgetMs = std::clamp(lastBudgetMs_, kMinBudgetMs, kMaxBudgetMs);
            // The effects with presets join it: they go on Auto.
            if (scene.fog.enabled) scene.fog.quality = postfx::FogQuality::Auto;
            if (scene.clouds.enabled) scene.clouds.quality = postfx::CloudQuality::Auto;
        } else {
            lastBudgetMs_ = scene.budgetMs;
            scene.budgetMs = 0.0f;
        }
    }
    tooltip(
        "postfx picks one preset per effect on quality auto: the lowest summed error (from the committed "
        "accuracy-cost fronts) whose measured GPU time fits the budget");
    if (on) {
        float ms = scene.budgetMs;
        if (ImGui::SliderFloat("budget [ms]", &ms, kMinBudgetMs, kMaxBudgetMs, "%.3g",
                               ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic)) {
            scene.budgetMs = std::clamp(ms, kMinBudgetMs, kMaxBudgetMs);
            changed = true;
        }
        tooltip("GPU time all of postfx's passes may take per frame");
        for (const std::string& line : budgetChoiceLines(scene, context))
            ImGui::TextUnformatted(line.c_str());
    }
    return changed;
}

}  // namespace demo::window
