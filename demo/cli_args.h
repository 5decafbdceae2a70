// Command-line pieces shared by postfx-render and postfx-demo: a usage error, and the integer and
// WIDTHxHEIGHT options with range checks that name the option in their message.
#pragma once

#include <charconv>
#include <cstdint>
#include <string>
#include <string_view>

namespace demo::cli {

struct UsageError {
    std::string message;
};

// A decimal integer in [lo, hi] and nothing else (no sign, no spaces).
inline bool parseUint(std::string_view text, uint32_t lo, uint32_t hi, uint32_t& out) {
    if (text.empty() || text.front() < '0' || text.front() > '9') return false;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc() && end == text.data() + text.size() && out >= lo && out <= hi;
}

// `option VALUE` as an integer in [lo, hi]; throws UsageError naming the option otherwise.
inline void uintOption(const std::string& option, const std::string& text, uint32_t lo, uint32_t hi,
                       uint32_t& out) {
    if (!parseUint(text, lo, hi, out))
        throw UsageError{option + " '" + text + "': expected an integer in " + std::to_string(lo) + ".." +
                         std::to_string(hi)};
}

// `--size WxH`, each side in [1, maxSide]; throws UsageError otherwise.
inline void sizeOption(const std::string& text, uint32_t maxSide, uint32_t& width, uint32_t& height) {
    const size_t x = text.find('x');
    if (x == std::string::npos || !parseUint(std::string_view(text).substr(0, x), 1, maxSide, width) ||
        !parseUint(std::string_view(text).substr(x + 1), 1, maxSide, height))
        throw UsageError{"--size '" + text + "': expected WIDTHxHEIGHT, each 1.." + std::to_string(maxSide)};
}

}  // namespace demo::cli
