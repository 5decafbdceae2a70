#include "stats.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <set>

namespace bench {

const char* methodName(Method method) {
    switch (method) {
        case Method::Ours:
            return "postfx-fog";
        case Method::SeedAsWritten:
            return "seed-as-written";
        case Method::SeedFixedRiemann:
            return "seed-fixed-riemann";
        case Method::Froxel:
            return "postfx-froxel";
    }
    return "unknown";
}

std::string Setting::label() const {
    char text[160];
    std::string noise = noiseSize ? " noise=" + std::to_string(noiseSize) : std::string();
    if (method == Method::Froxel) {
        std::string lightText =
            lights ? " lights=" + std::to_string(lights) + " lists=" + (lightLists ? "on" : "off")
                   : std::string();
        if (shadowedLights) lightText += " shadowed=" + std::to_string(shadowedLights);
        std::snprintf(text, sizeof text, "grid=%ux%ux%u dist=%s tricubic=%s%s%s", gridX, gridY, gridZ,
                      logSlices ? "log" : "power", tricubic ? "on" : "off", noise.c_str(), lightText.c_str());
    } else if (method == Method::Ours) {
        const std::string kernel = shadowKernel ? " kernel=" + std::to_string(shadowKernel) : std::string();
        std::snprintf(text, sizeof text, "steps=%u jitter=%s scale=%g%s%s", steps, jitter ? "on" : "off",
                      double(resolutionScale), kernel.c_str(), noise.c_str());
        if (!preset.empty()) return "preset=" + preset + " (" + text + ")";
    } else {
        std::snprintf(text, sizeof text, "step=%gm jitter=%s%s", double(stepLength), jitter ? "on" : "off",
                      noise.c_str());
    }
    return text;
}

double percentile(std::vector<double> values, double q) {
    if (values.empty()) return NAN;
    std::sort(values.begin(), values.end());
    const double position = std::clamp(q, 0.0, 1.0) * double(values.size() - 1);
    const size_t lo = size_t(std::floor(position));
    const size_t hi = std::min(lo + 1, values.size() - 1);
    return values[lo] + (values[hi] - values[lo]) * (position - double(lo));
}

Timing summarize(const std::vector<double>& frameTotals,
                 const std::vector<std::pair<std::string, std::vector<double>>>& passes) {
    Timing t;
    t.frames = uint32_t(frameTotals.size());
    t.median = percentile(frameTotals, 0.5);
    t.p10 = percentile(frameTotals, 0.1);
    t.p90 = percentile(frameTotals, 0.9);
    t.min = percentile(frameTotals, 0.0);
    t.max = percentile(frameTotals, 1.0);
    for (const auto& [name, ms] : passes)
        t.passMedians.emplace_back(name, percentile(ms, 0.5));
    return t;
}

std::vector<size_t> paretoFront(std::span<const double> x, std::span<const double> y) {
    std::vector<size_t> order;
    for (size_t i = 0; i < x.size() && i < y.size(); ++i)
        if (std::isfinite(x[i]) && std::isfinite(y[i])) order.push_back(i);
    // By x, then y: a point is on the front when its y is below every y before it.
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return x[a] != x[b] ? x[a] < x[b] : y[a] < y[b]; });
    std::vector<size_t> front;
    double best = INFINITY;
    for (size_t i : order) {
        if (y[i] < best) {
            front.push_back(i);
            best = y[i];
        }
    }
    return front;
}

void markParetoFronts(std::vector<Result>& results) {
    std::set<std::string> scenes;
    for (const Result& r : results)
        scenes.insert(r.setting.scene);
    for (const std::string& scene : scenes) {
        std::vector<size_t> ours;
        for (size_t i = 0; i < results.size(); ++i)
            if (results[i].setting.scene == scene && results[i].setting.method == Method::Ours &&
                results[i].setting.preset.empty())
                ours.push_back(i);
        std::vector<double> time, error1, error16;
        for (size_t i : ours) {
            time.push_back(results[i].timing.median);
            error1.push_back(results[i].error[0].relativeRmse);
            error16.push_back(results[i].error[2].relativeRmse);
        }
        for (size_t k : paretoFront(time, error1))
            results[ours[k]].pareto1 = true;
        for (size_t k : paretoFront(time, error16))
            results[ours[k]].pareto16 = true;
    }
}

double tonemappedRmse(std::span<const float> actual, std::span<const float> expected) {
    const size_t pixels = std::min(actual.size(), expected.size()) / 4;
    auto luminance = [](const float* p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; };
    double logSum = 0.0;
    size_t lit = 0;
    for (size_t p = 0; p < pixels; ++p) {
        const double y = luminance(&expected[p * 4]);
        if (y > 0.0 && std::isfinite(y)) logSum += std::log(y), ++lit;
    }
    const double k = lit ? 0.18 / std::exp(logSum / double(lit)) : 1.0;
    auto tonemap = [k](double v) { return k * v / (1.0 + k * std::abs(v)); };
    double errorSquared = 0.0, referenceSquared = 0.0;
    for (size_t p = 0; p < pixels; ++p) {
        for (size_t c = 0; c < 3; ++c) {
            const double a = actual[p * 4 + c], b = expected[p * 4 + c];
            if (!std::isfinite(a) || !std::isfinite(b)) continue;
            const double tb = tonemap(b), d = tonemap(a) - tb;
            errorSquared += d * d;
            referenceSquared += tb * tb;
        }
    }
    if (referenceSquared > 0.0) return std::sqrt(errorSquared / referenceSquared);
    return errorSquared > 0.0 ? INFINITY : 0.0;
}

double calibrationDrift(double beforeMs, double afterMs, double referenceMs) {
    if (!std::isfinite(beforeMs) || !std::isfinite(afterMs) || beforeMs <= 0.0 || afterMs <= 0.0) return NAN;
    double drift = std::abs(afterMs / beforeMs - 1.0);
    if (std::isfinite(referenceMs) && referenceMs > 0.0)
        drift =
            std::max({drift, std::abs(beforeMs / referenceMs - 1.0), std::abs(afterMs / referenceMs - 1.0)});
    return drift;
}

RepeatSpread repeatSpread(const std::vector<Result>& results) {
    std::map<std::string, std::vector<double>> medians;
    for (const Result& r : results)
        if (std::isfinite(r.timing.median))
            medians[r.setting.scene + " " + methodName(r.setting.method) + " " + r.setting.label()].push_back(
                r.timing.median);
    RepeatSpread out;
    for (const auto& [what, values] : medians) {
        if (values.size() < 2) continue;
        ++out.settings;
        const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
        const double spread = *hi / *lo - 1.0;
        if (!(spread <= out.spread)) out.spread = spread, out.worst = what;
    }
    return out;
}

CalibrationSpread calibrationSpread(const CalibrationLog& log) {
    CalibrationSpread s;
    std::vector<double> values;
    for (double v : log.measurements)
        if (std::isfinite(v)) values.push_back(v);
    s.count = values.size();
    if (values.empty()) return s;
    s.min = percentile(values, 0.0);
    s.median = percentile(values, 0.5);
    s.max = percentile(values, 1.0);
    s.ratio = s.max / s.min;
    return s;
}

}  // namespace bench
