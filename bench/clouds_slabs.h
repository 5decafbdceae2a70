// postfx-bench --clouds-slabs (docs/accuracy-cost/README.md, "Clouds against the path tracer"): the clouds'
// multiple-scattering models against the path-traced truth on homogeneous layers, CPU only. A flat layer
// 1000–1500 m of optical depth 0.5 to 50, albedo 0.9 to 1, one Henyey–Greenstein lobe of g 0.2 to 0.8, lit
// by the sun alone (ahead 45° up, overhead, behind 45° up), seen from below (60° up), from inside (20° up)
// and from above (60° down); and the published case (optical depth 5, albedo 1, g 0.6, the camera on the
// ground looking 60° up, the sun 45° up and 15° from the view). For each, the truth (clouds::
// estimateRadiance), the slab model and two octave settings (clouds::march in double, finely stepped: the
// models' error without discretisation). Writes results.md and results.csv.
#pragma once

#include <cstdint>
#include <string>

namespace bench {

struct CloudsSlabsArgs {
    uint32_t paths = 20000;  // paths per case
    uint32_t threads = 0;    // 0: every hardware thread
    std::string out;
};

int runCloudsSlabs(const CloudsSlabsArgs& args, const std::string& commandLine, const std::string& date);

}  // namespace bench
