// plot.svg: one log–log panel per scene, relative RMSE of linear radiance against GPU time, postfx's
// settings as points with their Pareto fronts (one frame, mean of 16) drawn as lines, each baseline as a
// polyline over its step lengths; a legend and the run's header.
#include "conclusions.h"
#include "report.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

namespace bench {
namespace {

constexpr double kPanelWidth = 440, kPanelHeight = 340;             // whole panel
constexpr double kLeft = 62, kRight = 14, kTop = 30, kBottom = 46;  // plot area margins in a panel
constexpr int kPanelsPerRow = 3;
constexpr double kHeaderHeight = 86, kLegendHeight = 76;

const char* kOursColor = "#1f6fb4";
const char* kOurs16Color = "#2a9d3a";
const char* kScaledColor = "#7b3294";    // postfx-fog at resolution scale < 1 (one frame)
const char* kPresetColor = "#111111";    // the committed presets' letters
const char* kProposedColor = "#111111";  // the proposed presets' letters (italic)
const char* kAsWrittenColor = "#e8780c";
const char* kFixedColor = "#c62828";

struct Axis {
    double lo = 0, hi = 1;  // log10 of the range, whole decades
    double pixelLo = 0, pixelHi = 1;
    double map(double v) const { return pixelLo + (std::log10(v) - lo) / (hi - lo) * (pixelHi - pixelLo); }
};

Axis decadeAxis(const std::vector<double>& values, double pixelLo, double pixelHi) {
    double mn = INFINITY, mx = -INFINITY;
    for (double v : values) {
        if (!(v > 0) || !std::isfinite(v)) continue;
        mn = std::min(mn, v);
        mx = std::max(mx, v);
    }
    Axis a;
    a.pixelLo = pixelLo;
    a.pixelHi = pixelHi;
    if (!std::isfinite(mn)) return a;  // nothing to plot: 1..10
    a.lo = std::floor(std::log10(mn));
    a.hi = std::ceil(std::log10(mx));
    if (a.hi <= a.lo) a.hi = a.lo + 1;
    return a;
}

std::string tickLabel(int exponent, bool asPercent) {
    // Percent labels for errors (10^-2 -> "1%"), plain decimals for milliseconds.
    const int e = asPercent ? exponent + 2 : exponent;
    std::string text;
    if (e >= 0) {
        text = "1" + std::string(size_t(e), '0');
    } else {
        text = "0." + std::string(size_t(-e - 1), '0') + "1";
    }
    return asPercent ? text + "%" : text;
}

std::string num(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", v);
    return text;
}

std::string marker(const std::string& shape, double x, double y, const char* color, bool filled,
                   const std::string& title) {
    std::ostringstream s;
    const std::string fill = filled ? color : "white";
    s << "<g><title>" << xmlEscape(title) << "</title>";
    if (shape == "circle") {
        s << "<circle cx=\"" << num(x) << "\" cy=\"" << num(y) << "\" r=\"3.6\" fill=\"" << fill
          << "\" stroke=\"" << color << "\" stroke-width=\"1.4\"/>";
    } else if (shape == "square") {
        s << "<rect x=\"" << num(x - 3.3) << "\" y=\"" << num(y - 3.3)
          << "\" width=\"6.6\" height=\"6.6\" fill=\"" << fill << "\" stroke=\"" << color
          << "\" stroke-width=\"1.4\"/>";
    } else if (shape == "triangle") {
        s << "<path d=\"M" << num(x) << " " << num(y - 4.2) << " L" << num(x + 4) << " " << num(y + 3) << " L"
          << num(x - 4) << " " << num(y + 3) << " Z\" fill=\"" << fill << "\" stroke=\"" << color
          << "\" stroke-width=\"1.4\"/>";
    } else {  // diamond
        s << "<path d=\"M" << num(x) << " " << num(y - 4) << " L" << num(x + 4) << " " << num(y) << " L"
          << num(x) << " " << num(y + 4) << " L" << num(x - 4) << " " << num(y) << " Z\" fill=\"" << fill
          << "\" stroke=\"" << color << "\" stroke-width=\"1.2\"/>";
    }
    s << "</g>\n";
    return s.str();
}

std::string polyline(const std::vector<std::pair<double, double>>& points, const char* color, bool dashed,
                     double width) {
    if (points.size() < 2) return "";
    std::ostringstream s;
    s << "<polyline fill=\"none\" stroke=\"" << color << "\" stroke-width=\"" << width << "\"";
    if (dashed) s << " stroke-dasharray=\"5 3\"";
    s << " points=\"";
    for (const auto& [x, y] : points)
        s << num(x) << "," << num(y) << " ";
    s << "\"/>\n";
    return s.str();
}

bool plottable(double t, double e) {
    return t > 0 && std::isfinite(t) && e > 0 && std::isfinite(e);
}

// `proposed`: the presets this run proposes, drawn on the scene they were chosen on (else empty).
std::string panel(const std::string& scene, const std::vector<Result>& results,
                  const std::vector<ProposedPreset>& proposed, double originX, double originY) {
    std::vector<const Result*> rows;
    std::vector<double> times, errors;
    for (const Result& r : results) {
        if (r.setting.scene != scene) continue;
        rows.push_back(&r);
        times.push_back(r.timing.median);
        errors.push_back(r.error[0].relativeRmse);
        errors.push_back(r.error[2].relativeRmse);
    }
    const double x0 = originX + kLeft, x1 = originX + kPanelWidth - kRight;
    const double y0 = originY + kPanelHeight - kBottom, y1 = originY + kTop;  // y0: bottom
    const Axis ax = decadeAxis(times, x0, x1);
    const Axis ay = decadeAxis(errors, y0, y1);

    std::ostringstream s;
    s << "<g>\n<text x=\"" << num((x0 + x1) / 2) << "\" y=\"" << num(originY + 18)
      << "\" text-anchor=\"middle\" font-size=\"14\" font-weight=\"bold\">" << xmlEscape(scene)
      << "</text>\n";
    s << "<rect x=\"" << num(x0) << "\" y=\"" << num(y1) << "\" width=\"" << num(x1 - x0) << "\" height=\""
      << num(y0 - y1) << "\" fill=\"none\" stroke=\"#444\" stroke-width=\"1\"/>\n";
    // Ticks and grid: decades labelled, 2..9 minor.
    for (int axis = 0; axis < 2; ++axis) {
        const Axis& a = axis == 0 ? ax : ay;
        for (int e = int(a.lo); e <= int(a.hi); ++e) {
            for (int m = 1; m <= 9; ++m) {
                const double v = m * std::pow(10.0, e);
                if (std::log10(v) > a.hi + 1e-9) break;
                const double p = a.map(v);
                const bool major = m == 1;
                if (axis == 0) {
                    s << "<line x1=\"" << num(p) << "\" y1=\"" << num(y1) << "\" x2=\"" << num(p)
                      << "\" y2=\"" << num(y0) << "\" stroke=\"" << (major ? "#ccc" : "#eee")
                      << "\" stroke-width=\"0.8\"/>\n";
                    s << "<line x1=\"" << num(p) << "\" y1=\"" << num(y0) << "\" x2=\"" << num(p)
                      << "\" y2=\"" << num(y0 + (major ? 6 : 3))
                      << "\" stroke=\"#444\" stroke-width=\"1\"/>\n";
                    if (major)
                        s << "<text x=\"" << num(p) << "\" y=\"" << num(y0 + 18)
                          << "\" text-anchor=\"middle\" font-size=\"11\">" << tickLabel(e, false)
                          << "</text>\n";
                } else {
                    s << "<line x1=\"" << num(x0) << "\" y1=\"" << num(p) << "\" x2=\"" << num(x1)
                      << "\" y2=\"" << num(p) << "\" stroke=\"" << (major ? "#ccc" : "#eee")
                      << "\" stroke-width=\"0.8\"/>\n";
                    s << "<line x1=\"" << num(x0 - (major ? 6 : 3)) << "\" y1=\"" << num(p) << "\" x2=\""
                      << num(x0) << "\" y2=\"" << num(p) << "\" stroke=\"#444\" stroke-width=\"1\"/>\n";
                    if (major)
                        s << "<text x=\"" << num(x0 - 8) << "\" y=\"" << num(p + 4)
                          << "\" text-anchor=\"end\" font-size=\"11\">" << tickLabel(e, true) << "</text>\n";
                }
            }
        }
    }
    s << "<text x=\"" << num((x0 + x1) / 2) << "\" y=\"" << num(y0 + 36)
      << "\" text-anchor=\"middle\" font-size=\"12\">GPU time per frame [ms]</text>\n";
    s << "<text transform=\"translate(" << num(originX + 14) << " " << num((y0 + y1) / 2)
      << ") rotate(-90)\" text-anchor=\"middle\" font-size=\"12\">relative RMSE</text>\n";

    // Baselines: polylines over their step lengths, one frame solid and filled, the mean of 16 frames
    // dashed and hollow.
    for (Method method : {Method::SeedAsWritten, Method::SeedFixedRiemann}) {
        const char* color = method == Method::SeedAsWritten ? kAsWrittenColor : kFixedColor;
        for (int which : {2, 0}) {
            std::vector<const Result*> pts;
            for (const Result* r : rows)
                if (r->setting.method == method && plottable(r->timing.median, r->error[which].relativeRmse))
                    pts.push_back(r);
            std::sort(pts.begin(), pts.end(), [](const Result* a, const Result* b) {
                return a->setting.stepLength > b->setting.stepLength;
            });
            std::vector<std::pair<double, double>> line;
            for (const Result* r : pts)
                line.emplace_back(ax.map(r->timing.median), ay.map(r->error[which].relativeRmse));
            s << polyline(line, color, which != 0, 1.4);
            for (const Result* r : pts)
                s << marker(method == Method::SeedAsWritten ? "square" : "triangle", ax.map(r->timing.median),
                            ay.map(r->error[which].relativeRmse), color, which == 0,
                            std::string(methodName(method)) + " " + r->setting.label() +
                                (which == 0 ? "" : ", mean of 16 frames") + ": " +
                                formatNumber(r->timing.median, 4) + " ms, " +
                                formatNumber(r->error[which].relativeRmse * 100, 3) + "%");
        }
    }
    // Ours: the two Pareto fronts as lines, then every setting's markers.
    for (int which = 0; which < 2; ++which) {
        std::vector<const Result*> front;
        for (const Result* r : rows)
            if (r->setting.method == Method::Ours && (which == 0 ? r->pareto1 : r->pareto16))
                front.push_back(r);
        std::sort(front.begin(), front.end(),
                  [](const Result* a, const Result* b) { return a->timing.median < b->timing.median; });
        std::vector<std::pair<double, double>> line;
        for (const Result* r : front) {
            const double e = r->error[which == 0 ? 0 : 2].relativeRmse;
            if (plottable(r->timing.median, e)) line.emplace_back(ax.map(r->timing.median), ay.map(e));
        }
        s << polyline(line, which == 0 ? kOursColor : kOurs16Color, which == 1, 2.0);
    }
    for (const Result* r : rows) {
        if (r->setting.method != Method::Ours) continue;
        const double t = r->timing.median;
        const std::string what = "postfx-fog " + r->setting.label();
        if (!r->setting.preset.empty()) {
            // A preset repeats a sweep point (or a neighbour of one): its initial beside its one-frame point.
            if (!plottable(t, r->error[0].relativeRmse)) continue;
            const char initial = char(std::toupper(static_cast<unsigned char>(r->setting.preset[0])));
            s << "<g><title>"
              << xmlEscape(what + ": " + formatNumber(t, 4) + " ms, " +
                           formatNumber(r->error[0].relativeRmse * 100, 3) + "% (one frame)")
              << "</title><text x=\"" << num(ax.map(t) + 5) << "\" y=\""
              << num(ay.map(r->error[0].relativeRmse) - 5)
              << "\" font-size=\"11\" font-weight=\"bold\" fill=\"" << kPresetColor << "\">" << initial
              << "</text></g>\n";
            continue;
        }
        const char* oneFrameColor = r->setting.resolutionScale < 1.0f ? kScaledColor : kOursColor;
        if (r->setting.jitter && plottable(t, r->error[2].relativeRmse))
            s << marker("diamond", ax.map(t), ay.map(r->error[2].relativeRmse), kOurs16Color, true,
                        what + ", mean of 16 frames: " + formatNumber(t, 4) + " ms, " +
                            formatNumber(r->error[2].relativeRmse * 100, 3) + "%" +
                            (r->pareto16 ? " (Pareto)" : ""));
        if (plottable(t, r->error[0].relativeRmse))
            s << marker(
                "circle", ax.map(t), ay.map(r->error[0].relativeRmse), oneFrameColor, r->setting.jitter,
                what + ": " + formatNumber(t, 4) + " ms, " + formatNumber(r->error[0].relativeRmse * 100, 3) +
                    "%" + (r->pareto1 ? " (Pareto)" : ""));
    }
    // The proposed presets: lowercase initials (several where presets share a setting) at the 16-frame
    // point the rule chose them by.
    for (size_t i = 0; i < proposed.size(); ++i) {
        const Result* row = proposed[i].row;
        if (!row || !plottable(row->timing.median, row->error[2].relativeRmse)) continue;
        bool drawn = false;
        for (size_t k = 0; k < i; ++k)
            drawn = drawn || proposed[k].row == row;
        if (drawn) continue;
        std::string initials, names;
        for (const ProposedPreset& p : proposed)
            if (p.row == row) {
                initials += p.budget.name[0];
                names += (names.empty() ? "" : ", ") + p.budget.name;
            }
        const double t = row->timing.median, e = row->error[2].relativeRmse;
        s << "<g><title>"
          << xmlEscape("proposed " + names + ": " + row->setting.label() + ", " + formatNumber(t, 4) +
                       " ms, " + formatNumber(e * 100, 3) + "% (mean of 16 frames)")
          << "</title><text x=\"" << num(ax.map(t) - 5) << "\" y=\"" << num(ay.map(e) + 14)
          << "\" text-anchor=\"end\" font-size=\"11\" font-style=\"italic\" fill=\"" << kProposedColor
          << "\">" << initials << "</text></g>\n";
    }
    s << "</g>\n";
    return s.str();
}

}  // namespace

bool writeSvg(const std::string& path, const RunInfo& info, const std::vector<Result>& results,
              std::string& error) {
    const std::vector<std::string> scenes = sceneOrder(results);
    const int panels = std::max<int>(1, int(scenes.size()));
    const int columns = std::min(panels, kPanelsPerRow);
    const int rowsOfPanels = (panels + kPanelsPerRow - 1) / kPanelsPerRow;
    const double width = std::max(columns * kPanelWidth, 3 * kPanelWidth);
    const double height = kHeaderHeight + rowsOfPanels * kPanelHeight + kLegendHeight;

    std::ostringstream s;
    s << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(width) << "\" height=\"" << num(height)
      << "\" viewBox=\"0 0 " << num(width) << " " << num(height) << "\" font-family=\"sans-serif\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"12\" y=\"22\" font-size=\"16\" font-weight=\"bold\">postfx fog: error against GPU time "
         "(log–log) — relative RMSE of linear radiance vs the CPU reference</text>\n"
      << "<text x=\"12\" y=\"42\" font-size=\"11\">" << xmlEscape(info.device) << " · Vulkan "
      << xmlEscape(info.vulkanApi) << " · " << xmlEscape(info.date) << " · " << info.width << "×"
      << info.height
      << (info.errorStride > 1 ? " (error on every " + std::to_string(info.errorStride) + "th pixel)" : "")
      << " · reference " << info.referenceSteps << " steps · median of " << info.frames << " frames</text>\n"
      << "<text x=\"12\" y=\"58\" font-size=\"10\" fill=\"#555\">" << xmlEscape(info.commandLine)
      << "</text>\n"
      << "<text x=\"12\" y=\"74\" font-size=\"10\" fill=\"#555\">Filled: one frame; hollow or dashed: "
         "mean of 16 jittered frames (jitter-off points are the same for both). Markers carry tooltips with "
         "the setting.</text>\n";
    for (size_t i = 0; i < scenes.size(); ++i) {
        const double ox = double(i % kPanelsPerRow) * kPanelWidth;
        const double oy = kHeaderHeight + double(i / kPanelsPerRow) * kPanelHeight;
        const std::vector<ProposedPreset> proposed =
            scenes[i] == info.presetScene ? proposePresets(info, results) : std::vector<ProposedPreset>{};
        s << panel(scenes[i], results, proposed, ox, oy);
    }

    // Legend.
    const double ly = kHeaderHeight + rowsOfPanels * kPanelHeight + 18;
    struct Entry {
        std::string shape;
        const char* color;
        bool filled;
        bool line;
        bool dashed;
        std::string text;
    };
    const std::vector<Entry> entries = {
        {"circle", kOursColor, true, false, false, "postfx-fog, jitter on (1 frame)"},
        {"circle", kOursColor, false, false, false, "postfx-fog, jitter off"},
        {"circle", kScaledColor, true, false, false,
         "postfx-fog at resolution scale < 1 (hollow: jitter off)"},
        {"", kOursColor, false, true, false, "its Pareto front (1 frame)"},
        {"diamond", kOurs16Color, true, true, true, "postfx-fog, mean of 16 jittered frames; front dashed"},
        {"square", kAsWrittenColor, true, true, false, "seed shader as written (over step lengths)"},
        {"triangle", kFixedColor, true, true, false, "seed fixed, Riemann sum (over step lengths)"},
        {"", kPresetColor, false, false, false, "L, M, H, U: the quality presets low … ultra (one frame)"},
        {"", kProposedColor, false, false, false,
         "l, m, h, u: the presets this run proposes (results.md; at their 16-frame point)"},
    };
    double lx = 16;
    double row = ly;
    for (const Entry& e : entries) {
        const double entryWidth = 40 + 6.2 * double(e.text.size());
        if (lx + entryWidth > width) {
            lx = 16;
            row += 20;
        }
        if (e.line)
            s << "<line x1=\"" << num(lx) << "\" y1=\"" << num(row) << "\" x2=\"" << num(lx + 26)
              << "\" y2=\"" << num(row) << "\" stroke=\"" << e.color << "\" stroke-width=\"2\""
              << (e.dashed ? " stroke-dasharray=\"5 3\"" : "") << "/>\n";
        if (!e.shape.empty()) s << marker(e.shape, lx + 13, row, e.color, e.filled, e.text);
        s << "<text x=\"" << num(lx + 32) << "\" y=\"" << num(row + 4) << "\" font-size=\"11\">"
          << xmlEscape(e.text) << "</text>\n";
        lx += entryWidth;
    }
    s << "</svg>\n";

    std::ofstream out(path, std::ios::binary);
    out << s.str();
    out.close();
    if (!out) {
        error = "cannot write '" + path + "'";
        return false;
    }
    return true;
}

}  // namespace bench
