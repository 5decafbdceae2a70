// compare_png: compares two 8-bit images (a screenshot and a reference) per RGB channel.
//   compare_png ACTUAL.png EXPECTED.png [--diff DIFF.png] [--max-mean L] [--over T] [--max-over-fraction F]
// Passes (exit 0) when
//   - the mean absolute difference per channel is below L levels (default 2),
//   - fewer than a fraction F (default 0.01) of the pixels differ by more than T levels (default 8) in
//     any channel,
//   - and ACTUAL is not blank: its channels span more than 8 levels (an all-black or one-colour window
//     fails even against a blank reference).
// Exit 1 when the images differ, 2 on usage or file errors. --diff writes |a - b| per channel, scaled
// by 8 (so one level is visible), as an RGB PNG.
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

struct Image {
    int width = 0, height = 0;
    std::vector<uint8_t> rgb;
};

bool load(const std::string& path, Image& image, std::string& error) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        error = "cannot read '" + path + "': " + OIIO::geterror();
        return false;
    }
    const OIIO::ImageSpec& spec = in->spec();
    const int channels = spec.nchannels;
    if (channels < 3) {
        error = "'" + path + "' has " + std::to_string(channels) + " channel(s), expected RGB(A)";
        return false;
    }
    std::vector<uint8_t> data(size_t(spec.width) * spec.height * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, data.data())) {
        error = "cannot read '" + path + "': " + in->geterror();
        return false;
    }
    image.width = spec.width;
    image.height = spec.height;
    image.rgb.resize(size_t(spec.width) * spec.height * 3);
    for (size_t i = 0; i < size_t(spec.width) * spec.height; ++i)
        for (int c = 0; c < 3; ++c)
            image.rgb[i * 3 + c] = data[i * channels + c];
    return true;
}

bool parseDouble(const char* text, double& out) {
    char* end = nullptr;
    out = std::strtod(text, &end);
    return end != text && *end == '\0';
}

int usage(const std::string& message) {
    std::fprintf(
        stderr,
        "compare_png: %s\nusage: compare_png ACTUAL.png EXPECTED.png [--diff DIFF.png] [--max-mean L] "
        "[--over T] [--max-over-fraction F]\n",
        message.c_str());
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    std::string actualPath, expectedPath, diffPath;
    double maxMean = 2.0, over = 8.0, maxOverFraction = 0.01;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto number = [&](double& out) { return i + 1 < argc && parseDouble(argv[++i], out); };
        if (a == "--diff" && i + 1 < argc) {
            diffPath = argv[++i];
        } else if (a == "--max-mean") {
            if (!number(maxMean)) return usage("--max-mean needs a number");
        } else if (a == "--over") {
            if (!number(over)) return usage("--over needs a number");
        } else if (a == "--max-over-fraction") {
            if (!number(maxOverFraction)) return usage("--max-over-fraction needs a number");
        } else if (!a.empty() && a[0] == '-') {
            return usage("unknown option '" + a + "'");
        } else if (actualPath.empty()) {
            actualPath = a;
        } else if (expectedPath.empty()) {
            expectedPath = a;
        } else {
            return usage("too many arguments");
        }
    }
    if (expectedPath.empty()) return usage("two images are needed");

    Image actual, expected;
    std::string error;
    if (!load(actualPath, actual, error) || !load(expectedPath, expected, error)) return usage(error);
    if (actual.width != expected.width || actual.height != expected.height) {
        std::printf("compare_png: FAIL: size %dx%d differs from the reference's %dx%d\n", actual.width,
                    actual.height, expected.width, expected.height);
        return 1;
    }

    const size_t pixels = size_t(actual.width) * actual.height;
    uint64_t sum = 0, pixelsOver = 0;
    int maxDiff = 0;
    uint8_t lo = 255, hi = 0;
    std::vector<uint8_t> diff(pixels * 3);
    for (size_t i = 0; i < pixels; ++i) {
        int pixelMax = 0;
        for (int c = 0; c < 3; ++c) {
            const uint8_t a = actual.rgb[i * 3 + c];
            const int d = std::abs(int(a) - int(expected.rgb[i * 3 + c]));
            sum += uint64_t(d);
            pixelMax = std::max(pixelMax, d);
            lo = std::min(lo, a);
            hi = std::max(hi, a);
            diff[i * 3 + c] = uint8_t(std::min(d * 8, 255));
        }
        maxDiff = std::max(maxDiff, pixelMax);
        if (pixelMax > over) ++pixelsOver;
    }
    const double mean = double(sum) / double(pixels * 3);
    const double overFraction = double(pixelsOver) / double(pixels);
    const bool blank = hi - lo <= 8;
    const bool pass = !blank && mean < maxMean && overFraction < maxOverFraction;
    std::printf(
        "compare_png: %s: mean |diff| %.4f levels per channel (limit %.2f), %.4f%% of pixels off by more "
        "than "
        "%.0f levels (limit %.2f%%), max %d levels; actual spans %d..%d%s\n",
        pass ? "PASS" : "FAIL", mean, maxMean, overFraction * 100.0, over, maxOverFraction * 100.0, maxDiff,
        int(lo), int(hi), blank ? " (blank image)" : "");

    if (!diffPath.empty()) {
        auto out = OIIO::ImageOutput::create(diffPath);
        const OIIO::ImageSpec spec(actual.width, actual.height, 3, OIIO::TypeDesc::UINT8);
        if (!out || !out->open(diffPath, spec) || !out->write_image(OIIO::TypeDesc::UINT8, diff.data()) ||
            !out->close()) {
            std::fprintf(stderr, "compare_png: cannot write '%s'\n", diffPath.c_str());
            return 2;
        }
    }
    return pass ? 0 : 1;
}
