// postfx-bench's clock calibration (docs/accuracy-cost/README.md, "Calibration"): a small fixed compute
// dispatch (bench/shaders/calibration.comp: the same ALU loop on the same small grid every time), timed
// with GPU timestamps as the rows are (a timestamp pair around each dispatch, the median of a few) right
// before and right after each row's timed frames. A row whose calibration moved by more than the tolerance
// (after against before, or either against the run's reference, taken at the start after a warm-up) is
// timed again, up to a few times; the attempt with the smallest drift is kept, flagged when it is still out
// of tolerance. On a GPU shared with other work or changing its clocks, the rows of one run stay comparable
// (or say that they are not).
#pragma once

#include "bench_types.h"

#include "host/vulkan_host.h"

#include <memory>
#include <string>

namespace bench {

struct CalibrationOptions {
    bool enabled = true;
    // The dispatch's work: `groups` workgroups of 64 invocations, each `iterations` steps of 4 multiply-adds;
    // 0: sized once at the start of the run, to the power of two nearest to take about `targetMs`, then the
    // same for the whole run (a fixed value: the same across runs too).
    uint32_t iterations = 0;
    double targetMs = 2.0;
    uint32_t groups = 1024;
    uint32_t repeats = 5;     // dispatches per measurement: their median
    double tolerance = 0.05;  // the drift above which a row is timed again
    uint32_t retries = 3;     // at most this many more attempts per row
};

class Calibration {
public:
    // The dispatch on `host`'s device and queue, recording into `log` (which outlives it; a run that makes
    // several devices, --frame's sizes, shares one log). Without timestamps on the queue, or with
    // options.enabled false, measurements are NaN and rows are timed once.
    static std::unique_ptr<Calibration> create(const demo::VulkanHost& host,
                                               const CalibrationOptions& options, CalibrationLog& log,
                                               std::string& error);
    ~Calibration();
    Calibration(const Calibration&) = delete;
    Calibration& operator=(const Calibration&) = delete;

    // Takes the run's reference unless `log` has one: sizes the work (options.iterations 0), dispatches
    // for at least `warmupMs` of wall time (and two), so the clocks have ramped up, then the median of three
    // measurements. With a reference in `log`, its work.
    bool reference(double warmupMs, std::string& error);
    // One measurement: the queue's work done first, then `repeats` dispatches, each between timestamps, in
    // one submission; their median [ms] (NaN when not enabled). Added to the log.
    bool measure(double& ms, std::string& error);

    bool enabled() const;
    CalibrationLog& log();

    struct Impl;

private:
    explicit Calibration(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

// One row's attempts, each bracketed by the calibration. The timing code's loop:
//     CalibratedRow row(calibration);   // nullptr: no calibration, one attempt
//     do {
//         warm-up frames (every frame retired);  row.before(error);
//         timed frames (every frame retired) into `attempt`;  row.after(error);
//         if (row.kept()) timing = attempt;
//     } while (row.again());
//     timing.calibration = row.finish();
class CalibratedRow {
public:
    explicit CalibratedRow(Calibration* calibration);
    bool before(std::string& error);
    bool after(std::string& error);
    // After after(): whether this attempt has the smallest drift so far (the first one always).
    bool kept() const { return keptThis_; }
    // Whether to time the row again: the kept attempt's drift is above the tolerance and retries remain.
    bool again() const;
    // The kept attempt's calibration; counts the row in the log (once).
    RowCalibration finish();

private:
    Calibration* calibration_;
    RowCalibration best_;
    double before_ = NAN;
    uint32_t attempts_ = 0;
    bool keptThis_ = false;
    bool finished_ = false;
};

}  // namespace bench
