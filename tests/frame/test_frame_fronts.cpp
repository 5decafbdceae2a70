// The preset errors that one budget for the frame weighs (Effect::presetErrors) against the committed
// accuracy–cost fronts they come from: the fog's docs/accuracy-cost/h100-presets/results.csv (16-frame
// relative RMSE of the preset= rows, the mean over fog_default, fog_height, fog_shadowed, fog_valley) and the
// clouds' docs/accuracy-cost/clouds/results.csv (converged still relative RMSE of the preset= rows, the
// mean over the views). A new benchmark run that moves them fails here until the tables follow.
#include "clouds/clouds_settings.h"
#include "fog/fog_settings.h"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Row = std::map<std::string, std::string>;

// A results.csv: '#' comment lines, then a header and rows (no quoted commas in these files).
std::vector<Row> readCsv(const std::string& path) {
    std::ifstream in(path);
    EXPECT_TRUE(in.good()) << "cannot open " << path;
    std::vector<std::string> header;
    std::vector<Row> rows;
    std::string line;
    auto split = [](const std::string& l) {
        std::vector<std::string> cells;
        std::stringstream ss(l);
        std::string cell;
        while (std::getline(ss, cell, ','))
            cells.push_back(cell);
        if (!l.empty() && l.back() == ',') cells.emplace_back();
        return cells;
    };
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        if (header.empty()) {
            header = split(line);
            continue;
        }
        const std::vector<std::string> cells = split(line);
        Row row;
        for (size_t i = 0; i < header.size() && i < cells.size(); ++i)
            row[header[i]] = cells[i];
        rows.push_back(std::move(row));
    }
    return rows;
}

double meanOf(const std::vector<Row>& rows, const std::function<bool(const Row&)>& take,
              const std::string& column, size_t expectedCount) {
    double sum = 0.0;
    size_t n = 0;
    for (const Row& r : rows)
        if (take(r)) sum += std::stod(r.at(column)), ++n;
    EXPECT_EQ(n, expectedCount) << column;
    return n ? sum / double(n) : 0.0;
}

const char* const kPresetNames[] = {"low", "medium", "high", "ultra"};

}  // namespace

TEST(FrameFronts, FogPresetErrorsAreTheCommittedFronts) {
    const std::vector<Row> rows =
        readCsv(std::string(POSTFX_SOURCE_DIR) + "/docs/accuracy-cost/h100-presets/results.csv");
    const std::vector<double> errors = postfx::fog::qualityPresetErrors();
    ASSERT_EQ(errors.size(), 4u);
    for (size_t p = 0; p < 4; ++p) {
        const std::string preset = kPresetNames[p];
        const double mean = meanOf(
            rows,
            [&](const Row& r) {
                const std::string& scene = r.at("scene");
                return r.at("method") == "postfx-fog" && r.at("preset") == preset &&
                       (scene == "fog_default" || scene == "fog_height" || scene == "fog_shadowed" ||
                        scene == "fog_valley");
            },
            "rel_rmse_16", 4);
        EXPECT_NEAR(errors[p], mean, 5e-4 * mean) << preset;
    }
}

TEST(FrameFronts, CloudsPresetErrorsAreTheCommittedFronts) {
    const std::vector<Row> rows =
        readCsv(std::string(POSTFX_SOURCE_DIR) + "/docs/accuracy-cost/clouds/results.csv");
    ASSERT_EQ(std::size(postfx::clouds::kQualityPresets), 4u);
    for (size_t p = 0; p < 4; ++p) {
        const std::string preset = kPresetNames[p];
        const double mean = meanOf(
            rows, [&](const Row& r) { return r.at("knob") == "preset" && r.at("value") == preset; },
            "still_rel_rmse", 3);
        EXPECT_NEAR(postfx::clouds::kQualityPresets[p].error, mean, 5e-4 * mean) << preset;
    }
}
