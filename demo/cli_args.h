// Command-line pieces shared by postfx-render, postfx-demo and postfx-bench: a usage error, an option's
// value, and integers, numbers, WIDTHxHEIGHT and comma-separated lists with range checks whose messages
// name the option and the text given.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

namespace demo::cli {

struct UsageError {
    std::string message;
};

// The value of the option argv[i] (argv[i + 1]), advancing i; throws UsageError "OPTION needs a value"
// when it is the last argument.
inline std::string optionValue(int argc, char** argv, int& i) {
    if (i + 1 >= argc) throw UsageError{std::string(argv[i]) + " needs a value"};
    return argv[++i];
}

// A decimal integer in [lo, hi] and nothing else (no sign, no spaces, no leading zeros).
inline bool parseUint(std::string_view text, uint32_t lo, uint32_t hi, uint32_t& out) {
    if (text.empty() || text.front() < '0' || text.front() > '9') return false;
    if (text.size() > 1 && text.front() == '0') return false;  // "0064": a typo more likely than 64
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc() && end == text.data() + text.size() && out >= lo && out <= hi;
}

// A finite number (as std::stod reads it) and nothing after it.
inline bool parseNumber(const std::string& text, double& out) {
    try {
        size_t used = 0;
        out = std::stod(text, &used);
        return used == text.size() && std::isfinite(out);
    } catch (const std::exception&) {
        return false;
    }
}

// The items of a comma-separated list; empty items are left out ("a,,b," is {a, b}).
inline std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> items;
    size_t start = 0;
    while (start <= text.size()) {
        const size_t comma = text.find(',', start);
        const std::string item =
            text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (!item.empty()) items.push_back(item);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return items;
}

// `option VALUE` as an integer in [lo, hi]; throws UsageError naming the option otherwise.
inline void uintOption(const std::string& option, const std::string& text, uint32_t lo, uint32_t hi,
                       uint32_t& out) {
    if (!parseUint(text, lo, hi, out))
        throw UsageError{option + " '" + text + "': expected an integer in " + std::to_string(lo) + ".." +
                         std::to_string(hi)};
}

// `option VALUE` as a number for which inRange(value) holds; throws UsageError
// "OPTION 'VALUE': expected EXPECTED" otherwise.
template <class InRange>
double numberOption(const std::string& option, const std::string& text, InRange inRange,
                    const std::string& expected) {
    double value = 0;
    if (!parseNumber(text, value) || !inRange(value))
        throw UsageError{option + " '" + text + "': expected " + expected};
    return value;
}

// `--size WxH`, each side in [1, maxSide]; throws UsageError otherwise.
inline void sizeOption(const std::string& text, uint32_t maxSide, uint32_t& width, uint32_t& height) {
    const size_t x = text.find('x');
    if (x == std::string::npos || !parseUint(std::string_view(text).substr(0, x), 1, maxSide, width) ||
        !parseUint(std::string_view(text).substr(x + 1), 1, maxSide, height))
        throw UsageError{"--size '" + text + "': expected WIDTHxHEIGHT, each 1.." + std::to_string(maxSide)};
}

// The memory postfx-render needs per image pixel, host and device together (lavapipe's device memory is
// host memory): measured peak RSS growth with the image size is about 55 bytes per pixel writing a PNG, 80
// an EXR and 120 with --reference (G-buffer, HDR image, readback, postfx's fog images, the float copy and
// the file's buffers); rounded up. docs/scene-format.md, "Limits".
constexpr uint64_t kRendererBytesPerPixel = 128;
// The most an image may need: 8192x8192 fits, 16384x16384 (32 GiB) does not.
constexpr uint64_t kImageMemoryBudget = uint64_t(8) << 30;

// `--size WxH` within kImageMemoryBudget; throws UsageError naming the size and the estimate otherwise,
// before anything is allocated.
inline void checkImageMemory(uint32_t width, uint32_t height) {
    const uint64_t bytes = uint64_t(width) * height * kRendererBytesPerPixel;
    if (bytes <= kImageMemoryBudget) return;
    const auto gib = [](uint64_t b) { return std::to_string((b + (uint64_t(1) << 30) - 1) >> 30); };
    throw UsageError{"--size " + std::to_string(width) + "x" + std::to_string(height) + ": needs about " +
                     gib(bytes) + " GiB (" + std::to_string(kRendererBytesPerPixel) +
                     " bytes per pixel), more than the budget of " + gib(kImageMemoryBudget) +
                     " GiB (at most " + std::to_string(kImageMemoryBudget / kRendererBytesPerPixel) +
                     " pixels, e.g. 8192x8192)"};
}

// `option LIST`: comma-separated integers in [lo, hi], at least one; throws UsageError
// "OPTION 'LIST': expected integers in LO..HI, comma-separated" or "OPTION is empty".
inline std::vector<uint32_t> uintListOption(const std::string& option, const std::string& text, uint32_t lo,
                                            uint32_t hi) {
    std::vector<uint32_t> out;
    for (const std::string& item : splitList(text)) {
        uint32_t v = 0;
        if (!parseUint(item, lo, hi, v))
            throw UsageError{option + " '" + text + "': expected integers in " + std::to_string(lo) + ".." +
                             std::to_string(hi) + ", comma-separated"};
        out.push_back(v);
    }
    if (out.empty()) throw UsageError{option + " is empty"};
    return out;
}

// `option LIST`: comma-separated numbers for which inRange holds, at least one; throws UsageError
// "OPTION 'LIST': expected EXPECTED, comma-separated" or "OPTION is empty".
template <class InRange>
std::vector<double> numberListOption(const std::string& option, const std::string& text, InRange inRange,
                                     const std::string& expected) {
    std::vector<double> out;
    for (const std::string& item : splitList(text)) {
        double v = 0;
        if (!parseNumber(item, v) || !inRange(v))
            throw UsageError{option + " '" + text + "': expected " + expected + ", comma-separated"};
        out.push_back(v);
    }
    if (out.empty()) throw UsageError{option + " is empty"};
    return out;
}

}  // namespace demo::cli
