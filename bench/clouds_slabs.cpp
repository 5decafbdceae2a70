#include "clouds_slabs.h"

#include "report.h"

#include "clouds/clouds_model.h"
#include "clouds/clouds_path_tracer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <thread>
#include <vector>

namespace bench {
namespace {

namespace cl = postfx::clouds;

constexpr double kBottom = 1000.0, kTop = 1500.0;
constexpr double kDegree = 3.14159265358979323846 / 180.0;
// Radiance below this fraction of the sun's illuminance [1/sr] is not compared (a thick absorbing layer
// seen against the sun transmits e^{-20} of it: no model or estimate is meaningful there).
constexpr double kFloor = 1e-6;

struct Case {
    std::string sun, view;
    double tau = 0, albedo = 0, g = 0;
    double bottom = kBottom, top = kTop;  // the layer [m]
    glm::dvec3 toSun{0.0}, camera{0.0}, d{0.0};
    // Results (per unit sun illuminance, the red channel: the media are grey).
    double truth = 0, truthError = 0, slab = 0, octaves2 = 0, octaves4 = 0, single = 0;
};

glm::dvec3 direction(double elevationDeg, double azimuthDeg) {
    const double e = elevationDeg * kDegree, a = azimuthDeg * kDegree;
    return {std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)};
}

std::vector<Case> grid() {
    std::vector<Case> out;
    // The published case: the sun 45° up, 15° (great circle) from the view 60° up.
    {
        Case c;
        c.sun = "published";
        c.view = "ground, 60° up";
        c.tau = 5.0;
        c.albedo = 1.0;
        c.g = 0.6;
        c.camera = {0.0, 0.0, 0.0};
        c.d = direction(60.0, 0.0);
        const double cosAz =
            (std::cos(15.0 * kDegree) - std::sin(60.0 * kDegree) * std::sin(45.0 * kDegree)) /
            (std::cos(60.0 * kDegree) * std::cos(45.0 * kDegree));
        c.toSun = direction(45.0, std::acos(cosAz) / kDegree);
        out.push_back(c);
    }
    // The densest demo fog as a slab: fog_valley's density 0.08 /m falling off at 0.25 /m has a vertical
    // optical depth of 0.32: a layer 0–4 m of 0.08 /m, albedo 0.9, g 0.5, seen from 1.7 m looking 2° up,
    // the sun 45° up ahead and behind (the fogs' single scattering against every order).
    for (int sun = 0; sun < 2; ++sun) {
        Case c;
        c.sun = sun == 0 ? "fog: ahead 45°" : "fog: behind 45°";
        c.view = "fog layer 0–4 m, 1.7 m, 2° up";
        c.tau = 0.32;
        c.albedo = 0.9;
        c.g = 0.5;
        c.bottom = 0.0;
        c.top = 4.0;
        c.camera = {0.0, 1.7, 0.0};
        c.d = direction(2.0, 0.0);
        c.toSun = direction(45.0, sun == 0 ? 0.0 : 180.0);
        out.push_back(c);
    }
    for (double tau : {0.5, 2.0, 5.0, 20.0, 50.0})
        for (double albedo : {0.9, 0.99, 1.0})
            for (double g : {0.2, 0.6, 0.8})
                for (int sun = 0; sun < 3; ++sun)
                    for (int view = 0; view < 3; ++view) {
                        Case c;
                        c.tau = tau;
                        c.albedo = albedo;
                        c.g = g;
                        c.sun = sun == 0 ? "ahead 45°" : sun == 1 ? "overhead" : "behind 45°";
                        c.toSun =
                            sun == 1 ? glm::dvec3(0.0, 1.0, 0.0) : direction(45.0, sun == 0 ? 0.0 : 180.0);
                        c.view = view == 0   ? "below, 60° up"
                                 : view == 1 ? "inside, 20° up"
                                             : "above, 60° down";
                        c.camera = {0.0,
                                    view == 0   ? kBottom - 100.0
                                    : view == 1 ? 0.5 * (kBottom + kTop)
                                                : kTop + 100.0,
                                    0.0};
                        c.d = direction(view == 0 ? 60.0 : view == 1 ? 20.0 : -60.0, 0.0);
                        out.push_back(c);
                    }
    return out;
}

cl::Model modelOf(const Case& c, postfx::CloudMultipleScattering ms) {
    postfx::FrameInfo f;
    postfx::CloudSettings& s = f.clouds;
    s.enabled = true;
    s.noise.enabled = false;
    s.coverage = 1.0f;
    s.bottomHeight = float(c.bottom);
    s.topHeight = float(c.top);
    s.density = float(c.tau / (c.top - c.bottom));
    s.albedo = float(c.albedo);
    s.anisotropyForward = float(c.g);
    s.lobeMix = 0.0f;
    s.multipleScattering = ms;
    s.lightDistance = 1e6f;
    s.maxDistance = 1e7f;
    f.sun.toSun = postfx::Vec3(c.toSun);
    f.sun.illuminance = postfx::Vec3(1.0f);
    f.camera.position = postfx::DVec3(c.camera);
    return cl::modelFrom(f, {}, {});
}

void evaluate(Case& c, uint32_t paths, uint64_t stream) {
    const cl::Model slab = modelOf(c, {});
    cl::PathOptions options;
    options.samples = paths;
    const cl::PathEstimate truth = cl::estimateRadiance(slab, glm::dvec3(0.0), c.d, 1e7, options, stream);
    c.truth = truth.radiance.x;
    c.truthError = truth.standardError.x;
    const auto marched = [&](const cl::Model& m) {
        return cl::march(m, c.d, 1e7, 2048, 0.5, 256).luminance.x;
    };
    c.slab = marched(slab);
    c.octaves2 = marched(modelOf(c, {postfx::CloudScatteringModel::Octaves, 2, 0.5f, 0.5f, 0.5f}));
    c.octaves4 = marched(modelOf(c, {postfx::CloudScatteringModel::Octaves, 4, 0.6f, 0.6f, 0.5f}));
    c.single = marched(modelOf(c, {postfx::CloudScatteringModel::Octaves, 1, 0.5f, 0.5f, 0.5f}));
}

double relative(double model, const Case& c) {
    return c.truth > kFloor ? model / c.truth - 1.0 : NAN;
}

struct Summary {
    size_t compared = 0, within = 0;
    double meanAbs = 0.0, worst = 0.0;
};

Summary summarize(const std::vector<Case>& cases, double Case::*model) {
    Summary s;
    for (const Case& c : cases) {
        const double r = relative(c.*model, c);
        if (!std::isfinite(r) || c.sun.rfind("fog", 0) == 0) continue;  // the layers only
        ++s.compared;
        s.within += std::abs(r) <= 0.10;
        s.meanAbs += std::abs(r);
        s.worst = std::max(s.worst, std::abs(r));
    }
    if (s.compared) s.meanAbs /= double(s.compared);
    return s;
}

std::string signedPercent(double r) {
    if (!std::isfinite(r)) return "–";
    return (r >= 0 ? "+" : "-") + percent(std::abs(r));
}

}  // namespace

int runCloudsSlabs(const CloudsSlabsArgs& args, const std::string& commandLine, const std::string& date) {
    std::vector<Case> cases = grid();
    const uint32_t threads = args.threads ? args.threads : std::max(1u, std::thread::hardware_concurrency());
    std::fprintf(stderr, "postfx-bench --clouds-slabs: %zu cases, %u paths each, %u threads\n", cases.size(),
                 args.paths, threads);
    const auto start = std::chrono::steady_clock::now();
    std::atomic<size_t> next{0};
    std::vector<std::thread> pool;
    for (uint32_t t = 0; t < threads; ++t)
        pool.emplace_back([&] {
            for (size_t i; (i = next++) < cases.size();)
                evaluate(cases[i], args.paths, i);
        });
    for (std::thread& t : pool)
        t.join();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    std::error_code ec;
    std::filesystem::create_directories(args.out, ec);
    std::ostringstream csv, md;
    csv << "# postfx-bench --clouds-slabs, " << date << ", `" << commandLine << "`\n"
        << "tau,albedo,g,sun,view,truth,truth_stderr,slab,octaves2,octaves4,single\n";
    for (const Case& c : cases)
        csv << c.tau << "," << c.albedo << "," << c.g << ",\"" << c.sun << "\",\"" << c.view << "\","
            << formatNumber(c.truth, 6) << "," << formatNumber(c.truthError, 4) << ","
            << formatNumber(c.slab, 6) << "," << formatNumber(c.octaves2, 6) << ","
            << formatNumber(c.octaves4, 6) << "\n";
    md << "# Clouds against the path tracer: homogeneous layers\n\n"
       << "Written by `postfx-bench --clouds-slabs` (docs/accuracy-cost/README.md, \"Clouds against the path "
          "tracer\"); every number in [results.csv](results.csv).\n\n"
       << "| | |\n|---|---|\n| date | " << date << " |\n| command | `" << commandLine << "` |\n"
       << "| cases | " << cases.size() << ", " << args.paths << " paths each, " << formatNumber(seconds, 3)
       << " s on " << threads << " threads |\n"
       << "| truth | clouds::estimateRadiance (every scattering order) |\n"
       << "| models | clouds::march in double, 2048 view × 256 light steps (no discretisation error): slab "
          "(the default), octaves 2 × 0.5/0.5/0.5 (the octave model's defaults), octaves 4 × 0.6/0.6/0.5 "
          "(the "
          "demo scenes' former setting) |\n"
       << "| compared | radiance above " << kFloor << " of the sun's illuminance per sr |\n\n"
       << "## Summary\n\nThe layers 1000–1500 m and the published case (not the fog's slab).\n\n| model | "
          "cases compared | within 10% | mean abs. error | worst "
          "|\n|---|---|---|---|---|\n";
    for (const auto& [name, member] :
         {std::pair{"slab", &Case::slab}, std::pair{"octaves 2", &Case::octaves2},
          std::pair{"octaves 4", &Case::octaves4}}) {
        const Summary s = summarize(cases, member);
        md << "| " << name << " | " << s.compared << " | " << s.within << " ("
           << percent(double(s.within) / s.compared) << ") | " << percent(s.meanAbs) << " | "
           << percent(s.worst) << " |\n";
    }
    md << "\n## Every case\n\nRadiance per unit sun illuminance [1/sr]; each model's error relative to the "
          "truth; single: single scattering alone (as the fogs).\n\n| τ | albedo | g | sun | view | truth (± "
          "1σ) | slab | octaves 2 | "
          "octaves 4 | single |\n|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Case& c : cases)
        md << "| " << c.tau << " | " << c.albedo << " | " << c.g << " | " << c.sun << " | " << c.view << " | "
           << formatNumber(c.truth, 4) << " (± " << percent(c.truth > 0 ? c.truthError / c.truth : NAN, 2)
           << ") | " << signedPercent(relative(c.slab, c)) << " | " << signedPercent(relative(c.octaves2, c))
           << " | " << signedPercent(relative(c.octaves4, c)) << " | " << signedPercent(relative(c.single, c))
           << " |\n";
    std::string error;
    if (!writeTextFile(args.out + "/results.csv", csv.str(), error) ||
        !writeTextFile(args.out + "/results.md", md.str(), error)) {
        std::fprintf(stderr, "postfx-bench: %s\n", error.c_str());
        return 1;
    }
    for (const auto& [name, member] :
         {std::pair{"slab", &Case::slab}, std::pair{"octaves 2", &Case::octaves2},
          std::pair{"octaves 4", &Case::octaves4}}) {
        const Summary s = summarize(cases, member);
        std::printf("%-10s within 10%%: %zu of %zu, mean |error| %s, worst %s\n", name, s.within, s.compared,
                    percent(s.meanAbs).c_str(), percent(s.worst).c_str());
    }
    std::printf(
        "published case: truth %.5f ± %.5f, slab %.5f, octaves 2 %.5f, octaves 4 %.5f (%.1f s)\nwrote %s\n",
        cases[0].truth, cases[0].truthError, cases[0].slab, cases[0].octaves2, cases[0].octaves4, seconds,
        (args.out + "/results.md").c_str());
    return 0;
}

}  // namespace bench
