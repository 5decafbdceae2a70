// postfx-bench --atmosphere-truth (atmosphere_truth.h).
#include "atmosphere_truth.h"

#include "atmosphere/atmosphere_path_tracer.h"
#include "atmosphere/atmosphere_reference.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace bench {
namespace {

using namespace postfx::atmosphere;

struct Media {
    const char* name;
    double mieScale;
};
constexpr Media kMedia[] = {{"earth", 1.0}, {"hazy", 5.0}};
constexpr double kAlbedos[] = {0.0, 0.3};
constexpr double kAltitudes[] = {0.0, 1000.0, 10000.0, 100000.0, 400000.0};
constexpr double kSunElevations[] = {60.0, 30.0, 10.0, 2.0, -2.0};
constexpr double kViewZeniths[] = {0.0, 45.0, 80.0, 85.0, 89.0, 95.0, 120.0};
constexpr double kAzimuths[] = {0.0, 90.0, 180.0};

}  // namespace

int runAtmosphereTruth(const AtmosphereTruthArgs& args, const std::string& commandLine,
                       const std::string& date) {
    const auto start = std::chrono::steady_clock::now();
    const std::filesystem::path out(args.out);
    if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
    // Written entry by entry: a run cut short keeps what it measured.
    std::ofstream csv(out);
    if (!csv) {
        std::fprintf(stderr, "postfx-bench: cannot write %s\n", args.out.c_str());
        return 1;
    }
    csv << "# postfx-bench --atmosphere-truth, " << date << ", `" << commandLine << "`\n"
        << "# the path tracer (postfx/src/atmosphere/atmosphere_path_tracer.h) of every order; luminance per "
           "unit "
           "sun illuminance [cd/m2 per lx]; se: the standard error of each mean\n"
        << "media,albedo,altitude_m,sun_elevation_deg,view_zenith_deg,azimuth_deg,r,g,b,se_r,se_g,se_b,"
           "paths\n";
    size_t entries = 0;
    for (const Media& media : kMedia)
        for (const double albedo : kAlbedos) {
            Model m;
            m.mieScattering *= media.mieScale;
            m.mieAbsorption *= media.mieScale;
            m.groundAlbedo = glm::dvec3(albedo);
            const std::shared_ptr<const TransmittanceTable> transmittance = sharedTransmittanceTable(m);
            for (const double altitude : kAltitudes)
                for (const double sunElevation : kSunElevations)
                    for (const double viewZenith : kViewZeniths)
                        for (const double azimuth : kAzimuths) {
                            if (viewZenith == 0.0 && azimuth != 0.0) continue;
                            const ViewSunRay ray =
                                viewSunRay(m, {viewZenith, sunElevation, azimuth, altitude});
                            Sun sun;
                            sun.toSun = ray.toSun;
                            glm::dvec3 sum(0.0), variance(0.0);  // Σ n·mean, Σ n²·se²
                            uint64_t paths = 0, batch = 0;
                            double error = 1.0;
                            while (paths < args.maxPaths && error > args.targetError) {
                                PathTracerOptions po;
                                po.paths = args.batchPaths;
                                po.seed = 1 + batch++ * 7919;
                                const PathTracerResult r =
                                    pathTraceViewRay(m, *transmittance, ray.origin, ray.dir, sun, po);
                                const double n = double(po.paths);
                                sum += n * r.luminance;
                                variance += n * n * r.standardError * r.standardError;
                                paths += po.paths;
                                error = 0.0;
                                for (int c = 0; c < 3; ++c) {
                                    const double mean = sum[c] / double(paths);
                                    const double se = std::sqrt(variance[c]) / double(paths);
                                    error = std::max(error, mean > 0.0 ? se / mean : (se > 0.0 ? 1.0 : 0.0));
                                }
                            }
                            const glm::dvec3 mean = sum / double(paths);
                            const glm::dvec3 se = glm::sqrt(variance) / double(paths);
                            char line[512];
                            std::snprintf(
                                line, sizeof line, "%s,%g,%g,%g,%g,%g,%.8g,%.8g,%.8g,%.4g,%.4g,%.4g,%llu\n",
                                media.name, albedo, altitude, sunElevation, viewZenith, azimuth, mean.x,
                                mean.y, mean.z, se.x, se.y, se.z, (unsigned long long)paths);
                            csv << line << std::flush;
                            ++entries;
                            if (entries % 50 == 0)
                                std::fprintf(
                                    stderr, "%zu entries, %.0f s\n", entries,
                                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
                                        .count());
                        }
        }
    if (!csv) {
        std::fprintf(stderr, "postfx-bench: cannot write %s\n", args.out.c_str());
        return 1;
    }
    std::printf("%zu entries in %.0f s: %s\n", entries,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                args.out.c_str());
    return 0;
}

}  // namespace bench
