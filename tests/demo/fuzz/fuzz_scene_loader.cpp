// libFuzzer target for the demo's scene loader (docs/scene-format.md; how to run it: run_fuzz.sh and
// docs/scene-format.md, "Fuzzing"). For any bytes, parseScene must either
//   - reject them with one line that starts with a key path ("camera.near: ...", "(root): ...") or a
//     position ("(line 3, column 7) ..."), or
//   - give a scene that renders (scene_oracle.h: finite camera matrices, shadow fit, exposure, meshes;
//     postfx's own checks accept the frame) and that sceneToJson writes back to the same scene.
// Anything else aborts, which libFuzzer reports as a crash and saves the input.
//
// Half of the mutations are JSON-aware (LLVMFuzzerCustomMutator): a number of a parseable input is
// replaced by a value at an edge (the limits, float's extremes, a power-of-ten rescale), an array
// element is repeated, or a registered effect's setting is put at an end of its table's range or just
// outside it, so that the values of valid scenes are searched, not only the syntax.
#include "scene_oracle.h"

#include "scene/scene.h"

#include <postfx/settings_table.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

extern "C" std::size_t LLVMFuzzerMutate(uint8_t* data, std::size_t size, std::size_t maxSize);

namespace {

using json = nlohmann::json;

// Values at the edges of the scene format's ranges and of float.
constexpr double kEdgeValues[] = {0.0,    -0.0,   1.0,          -1.0,   0.5,     1e-45, 1e-38, 1e-30,
                                  1e-6,   1e-3,   0.01,         179.0,  180.0,   1e6,   1e7,   1.0000001e7,
                                  1e9,    1e19,   3e38,         3.4e38, -3.4e38, -1e7,  -30.0, 30.0,
                                  4096.0, 4097.0, 4294967295.0, 8.0,    64.0,    512.0, 513.0};

void collect(json& j, std::vector<json*>& numbers, std::vector<json*>& arrays) {
    if (j.is_number()) numbers.push_back(&j);
    if (j.is_array() && !j.empty()) arrays.push_back(&j);
    if (j.is_structured())
        for (json& child : j)
            collect(child, numbers, arrays);
}

// A value of `f` at an end of its range or just outside it (the red team's cases), from its table.
json tableEdge(const postfx::SettingField& f, std::minstd_rand& rng) {
    const bool upper = rng() % 2 == 0;
    const double bound = upper ? f.max : f.min;
    if (!std::isfinite(bound)) return upper ? 3.4e38 : -3.4e38;
    const bool outside = rng() % 3 == 0;
    const bool integer = f.kind == postfx::SettingKind::Uint || f.kind == postfx::SettingKind::UVec2 ||
                         f.kind == postfx::SettingKind::UVec3;
    double v = bound;
    if (outside)
        v = integer ? bound + (upper ? 1.0 : -1.0)
                    : std::nextafter(float(bound), upper ? HUGE_VALF : -HUGE_VALF);
    const json number = integer ? json(std::max(0.0, v)) : json(v);
    const int components = f.kind == postfx::SettingKind::UVec2 ? 2
                           : f.kind == postfx::SettingKind::Vec3 || f.kind == postfx::SettingKind::Color ||
                                   f.kind == postfx::SettingKind::UVec3 ||
                                   f.kind == postfx::SettingKind::DVec3
                               ? 3
                               : 1;
    if (components == 1) return number;
    json a = json::array();
    for (int c = 0; c < components; ++c)
        a.push_back(number);
    return a;
}

// Puts a registered effect's setting (postfx::effectSettingsTables) at an end of its range, or just
// outside, into `j`'s effects: the ranges the tables document are searched, whatever the seeds hold.
bool mutateSetting(json& j, std::minstd_rand& rng) {
    if (!j.is_object()) return false;
    const auto effects = postfx::effectSettingsTables();
    const postfx::EffectSettingsTable& e = effects[rng() % effects.size()];
    const auto table = e.table();
    const postfx::SettingField& f = table[rng() % table.size()];
    if (!f.key || f.kind == postfx::SettingKind::Bool || f.kind == postfx::SettingKind::Enum ||
        f.kind == postfx::SettingKind::Opaque)
        return false;
    std::string pointer = std::string("/effects/") + e.key + "/" + f.key;
    std::replace(pointer.begin(), pointer.end(), '.', '/');
    try {
        j[json::json_pointer(pointer)] = tableEdge(f, rng);
        if (rng() % 2 == 0) j["effects"][e.key]["enabled"] = true;
    } catch (const json::exception&) {
        return false;  // a seed whose effects are not objects
    }
    return true;
}

// One JSON-aware mutation of `text`; false when it does not parse or has nothing to mutate.
bool mutateJson(std::string& text, std::minstd_rand& rng) {
    json j = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (j.is_discarded()) return false;
    if (rng() % 4 == 0) {
        if (!mutateSetting(j, rng)) return false;
        text = j.dump();
        return true;
    }
    std::vector<json*> numbers, arrays;
    collect(j, numbers, arrays);
    const auto pick = [&](std::size_t n) { return std::size_t(rng() % n); };
    if (!arrays.empty() && pick(8) == 0) {  // repeat an element (more objects)
        json& a = *arrays[pick(arrays.size())];
        const json copy = a[pick(a.size())];
        for (std::size_t k = 1 + pick(4); k > 0; --k)
            a.push_back(copy);
    } else if (!numbers.empty()) {
        json& n = *numbers[pick(numbers.size())];
        if (pick(2) == 0) {
            n = kEdgeValues[pick(std::size(kEdgeValues))] * (pick(2) ? 1.0 : -1.0);
        } else {  // rescale by a power of ten
            n = n.get<double>() * std::pow(10.0, double(int(pick(81)) - 40));
        }
    } else {
        return false;
    }
    text = j.dump();
    return true;
}

[[noreturn]] void report(const char* what, const std::string& detail) {
    std::fprintf(stderr, "fuzz_scene_loader: %s: %s\n", what, detail.c_str());
    std::abort();
}

// "(root): ...", "(line L, column C) ...", or a key path ("camera.near", "objects[2].radius",
// "[\"my key\"]") followed by ": ".
bool startsWithPath(const std::string& error) {
    if (error.rfind("(root): ", 0) == 0 || error.rfind("(line ", 0) == 0) return true;
    if (error.empty() || error.find(": ") == std::string::npos) return false;
    const char c = error[0];
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == '[';
}

}  // namespace

extern "C" std::size_t LLVMFuzzerCustomMutator(uint8_t* data, std::size_t size, std::size_t maxSize,
                                               unsigned int seed) {
    std::minstd_rand rng(seed);
    if (rng() % 2 == 0) {
        std::string text(reinterpret_cast<const char*>(data), size);
        if (mutateJson(text, rng) && text.size() <= maxSize) {
            std::memcpy(data, text.data(), text.size());
            return text.size();
        }
    }
    return LLVMFuzzerMutate(data, size, maxSize);
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    demo::Scene scene;
    std::string error;
    if (!demo::parseScene(text, scene, error)) {
        if (error.empty() || error.find('\n') != std::string::npos || error.find('\r') != std::string::npos)
            report("the error is not one line", error);
        if (!startsWithPath(error)) report("the error does not start with a key path", error);
        return 0;
    }
    if (const std::string problem = demo::fuzz::renderProblem(scene); !problem.empty())
        report("a scene that loads does not render", problem);

    demo::Scene again;
    if (!demo::parseScene(demo::sceneToJson(scene).dump(), again, error))
        report("sceneToJson's output does not load", error);
    if (demo::sceneToJson(again) != demo::sceneToJson(scene))
        report("sceneToJson does not round-trip", demo::sceneToJson(scene).dump());
    return 0;
}
