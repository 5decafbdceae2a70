// The atmosphere's model against path-traced truth (docs/effects/atmosphere.md, "Against the light"): the
// CPU reference (integrateViewRay, 1024 steps, the lit ground) with the scattering orders' table at the
// reference's default quality, and with Hillaire's Ψ for comparison, against every entry of
// tests/atmosphere/data/path_traced_sky.csv (postfx-bench --atmosphere-truth: five altitudes, five suns,
// seven view zeniths, three azimuths, albedo 0 and 0.3, Earth's media and a hazy one).
#include "atmosphere/atmosphere_orders.h"
#include "atmosphere/atmosphere_path_tracer.h"
#include "atmosphere/atmosphere_reference.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace postfx::atmosphere;

struct Entry {
    std::string media;
    double albedo = 0.0, altitude = 0.0, sunElevation = 0.0, viewZenith = 0.0, azimuth = 0.0;
    glm::dvec3 luminance{0.0}, standardError{0.0};
};

std::vector<Entry> readTable() {
    std::ifstream file(std::string(POSTFX_SOURCE_DIR) + "/tests/atmosphere/data/path_traced_sky.csv");
    std::vector<Entry> out;
    std::string line;
    bool header = false;
    while (std::getline(file, line)) {
        if (line.empty() || line[0] == '#') continue;
        if (!header) {
            header = true;  // the column names
            continue;
        }
        std::stringstream ss(line);
        std::string cell;
        std::vector<std::string> cells;
        while (std::getline(ss, cell, ','))
            cells.push_back(cell);
        if (cells.size() < 12) continue;
        Entry e;
        e.media = cells[0];
        e.albedo = std::stod(cells[1]);
        e.altitude = std::stod(cells[2]);
        e.sunElevation = std::stod(cells[3]);
        e.viewZenith = std::stod(cells[4]);
        e.azimuth = std::stod(cells[5]);
        for (int c = 0; c < 3; ++c) {
            e.luminance[c] = std::stod(cells[6 + c]);
            e.standardError[c] = std::stod(cells[9 + c]);
        }
        out.push_back(e);
    }
    return out;
}

Model modelOf(const Entry& e) {
    Model m;
    if (e.media == "hazy") {
        m.mieScattering *= 5.0;
        m.mieAbsorption *= 5.0;
    }
    m.groundAlbedo = glm::dvec3(e.albedo);
    return m;
}

// The MC error below which an entry is compared (the 0.3 %), and the model's tolerances: 2 % per
// channel, 1 % looking straight up, each widened by two standard errors of the truth.
constexpr double kComparedError = 0.003;
constexpr double kTolerance = 0.02, kZenithTolerance = 0.01;

// Per class of view: the largest |model/MC - 1| of each model.
struct Worst {
    double orders = 0.0, hillaire = 0.0;
    size_t count = 0;
};

TEST(AtmosphereTruth, ScatteringOrdersWithinTwoPercentOfThePathTracer) {
    const std::vector<Entry> table = readTable();
    ASSERT_GT(table.size(), 1000u) << "tests/atmosphere/data/path_traced_sky.csv";
    std::map<std::string, Worst> byClass;
    size_t compared = 0, skipped = 0, failed = 0;
    size_t dark = 0;
    for (const Entry& e : table) {
        if (e.luminance == glm::dvec3(0.0)) {
            // Nothing to see (space above the atmosphere, a black ground): the model must see nothing too.
            const Model m = modelOf(e);
            const ViewSunRay ray = viewSunRay(m, {e.viewZenith, e.sunElevation, e.azimuth, e.altitude});
            Sun sun;
            sun.toSun = ray.toSun;
            ViewRayOptions o;
            o.ground = true;
            o.ordersTable = sharedOrdersTable(m).get();
            o.transmittanceTable = sharedTransmittanceTable(m).get();
            EXPECT_EQ(integrateViewRay(m, ray.origin, ray.dir, sun, o).luminance, glm::dvec3(0.0))
                << e.media << " " << e.altitude << " m, view " << e.viewZenith;
            ++dark;
            continue;
        }
        double se = 0.0;
        for (int c = 0; c < 3; ++c)
            se = std::max(se, e.luminance[c] > 0.0 ? e.standardError[c] / e.luminance[c] : 1.0);
        if (se > kComparedError) {
            ++skipped;
            continue;
        }
        ++compared;
        const Model m = modelOf(e);
        const std::shared_ptr<const TransmittanceTable> transmittance = sharedTransmittanceTable(m);
        const std::shared_ptr<const OrdersTable> orders = sharedOrdersTable(m);
        const std::shared_ptr<const PsiTable> psi = sharedPsiTable(m);
        const ViewSunRay ray = viewSunRay(m, {e.viewZenith, e.sunElevation, e.azimuth, e.altitude});
        Sun sun;
        sun.toSun = ray.toSun;
        ViewRayOptions o;
        o.steps = 1024;
        o.ground = true;
        o.transmittanceTable = transmittance.get();
        o.ordersTable = orders.get();
        const glm::dvec3 model = integrateViewRay(m, ray.origin, ray.dir, sun, o).luminance;
        o.ordersTable = nullptr;
        o.psiTable = psi.get();
        const glm::dvec3 hillaire = integrateViewRay(m, ray.origin, ray.dir, sun, o).luminance;
        const bool zenith = e.viewZenith == 0.0;
        const std::string viewClass =
            e.viewZenith == 0.0    ? "zenith"
            : e.viewZenith > 90.0  ? "below the horizon"
            : e.viewZenith >= 80.0 ? (e.azimuth == 0.0 ? "horizon toward the sun" : "horizon away/across")
                                   : "sky 45°";
        const std::string key = (e.altitude >= 100000.0 ? "from space, " : "") + viewClass;
        Worst& w = byClass[key];
        ++w.count;
        for (int c = 0; c < 3; ++c) {
            const double err = model[c] / e.luminance[c] - 1.0, errH = hillaire[c] / e.luminance[c] - 1.0;
            w.orders = std::max(w.orders, std::abs(err));
            w.hillaire = std::max(w.hillaire, std::abs(errH));
            const double rel = e.standardError[c] / e.luminance[c];
            const double tolerance = (zenith ? kZenithTolerance : kTolerance) + 2.0 * rel;
            if (std::abs(err) > tolerance) {
                ++failed;
                ADD_FAILURE() << e.media << " albedo " << e.albedo << ", " << e.altitude << " m, sun "
                              << e.sunElevation << "°, view " << e.viewZenith << "° azimuth " << e.azimuth
                              << "°, channel " << c << ": model " << model[c] << " vs MC " << e.luminance[c]
                              << " ± " << e.standardError[c] << " (" << 100.0 * err << " %)";
            }
        }
    }
    std::printf(
        "[ measured ] %zu entries compared (MC error <= %.1f %%), %zu dark (both 0), %zu left out (MC error "
        "larger), %zu channels off\n",
        compared, 100.0 * kComparedError, dark, skipped, failed);
    for (const auto& [key, w] : byClass)
        std::printf("[ measured ] %-32s %4zu views: largest |error| orders %5.2f %%, hillaire %5.1f %%\n",
                    key.c_str(), w.count, 100.0 * w.orders, 100.0 * w.hillaire);
    EXPECT_GE(compared, 1100u);
}

}  // namespace
