#include "scene/json_text.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <system_error>

namespace demo::json_text {
namespace {

using json = nlohmann::json;

bool isIdentifier(std::string_view key) {
    if (key.empty() || key.size() > 40) return false;
    const auto alpha = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
    if (!alpha(key[0])) return false;
    return std::all_of(key.begin(), key.end(), [&](char c) { return alpha(c) || (c >= '0' && c <= '9'); });
}

bool isContinuation(unsigned char c) {
    return (c & 0xC0) == 0x80;
}

// Length of the valid UTF-8 sequence starting at s[i] and its code point, or 0 if invalid.
std::size_t decodeUtf8(std::string_view s, std::size_t i, uint32_t& codePoint) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char c = byte(i);
    std::size_t length = 0;
    unsigned char lo = 0x80, hi = 0xBF;  // allowed range of the second byte
    if (c < 0x80) {
        codePoint = c;
        return 1;
    } else if (c >= 0xC2 && c <= 0xDF) {
        length = 2;
        codePoint = c & 0x1F;
    } else if (c >= 0xE0 && c <= 0xEF) {
        length = 3;
        codePoint = c & 0x0F;
        if (c == 0xE0) lo = 0xA0;  // overlong
        if (c == 0xED) hi = 0x9F;  // surrogates
    } else if (c >= 0xF0 && c <= 0xF4) {
        length = 4;
        codePoint = c & 0x07;
        if (c == 0xF0) lo = 0x90;  // overlong
        if (c == 0xF4) hi = 0x8F;  // > U+10FFFF
    } else {
        return 0;
    }
    if (i + length > s.size()) return 0;
    if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
    for (std::size_t k = 1; k < length; ++k) {
        if (!isContinuation(byte(i + k))) return 0;
        codePoint = (codePoint << 6) | (byte(i + k) & 0x3F);
    }
    return length;
}

// nlohmann's "...; last read: '<text>'; expected ..." can quote a long stretch of the input (a whole
// string before the offending byte): keep only the end of it, which is where the error is.
std::string shortenLastRead(std::string_view detail) {
    constexpr std::string_view kLastRead = "last read: '";
    constexpr std::size_t kKeep = 40;
    const std::size_t start = detail.find(kLastRead);
    if (start == std::string_view::npos) return std::string(detail);
    const std::size_t from = start + kLastRead.size();
    std::size_t end = detail.find("'; expected ", from);
    if (end == std::string_view::npos) end = detail.rfind('\'');
    if (end == std::string_view::npos || end < from || end - from <= kKeep) return std::string(detail);
    std::size_t cut = end - kKeep;
    while (cut < end && isContinuation(static_cast<unsigned char>(detail[cut])))
        ++cut;
    return std::string(detail.substr(0, from)) + "..." + std::string(detail.substr(cut));
}

std::string dumpCompact(const json& j) {
    return j.dump(-1, ' ', false, json::error_handler_t::replace);
}

}  // namespace

std::string keyPath(const std::string& path, std::string_view key) {
    if (isIdentifier(key)) return path.empty() ? std::string(key) : path + "." + std::string(key);
    return path + "[" + quote(key) + "]";
}

std::string indexPath(const std::string& path, std::size_t index) {
    return path + "[" + std::to_string(index) + "]";
}

std::string describe(const json& value) {
    switch (value.type()) {
        case json::value_t::null:
            return "null";
        case json::value_t::boolean:
            return value.get<bool>() ? "true" : "false";
        case json::value_t::number_integer:
        case json::value_t::number_unsigned:
            return value.dump();
        case json::value_t::number_float: {
            const double d = value.get<double>();
            if (std::isnan(d)) return "nan";
            if (std::isinf(d)) return d > 0 ? "inf" : "-inf";
            return value.dump();
        }
        case json::value_t::string:
            return "the string " + quote(value.get_ref<const std::string&>());
        case json::value_t::array: {
            if (value.empty()) return "an empty array";
            const bool flat =
                value.size() <= 4 &&
                std::none_of(value.begin(), value.end(), [](const json& e) { return e.is_structured(); });
            if (flat) {
                std::string text = dumpCompact(value);
                if (text.size() <= 60) return text;
            }
            return "an array of " + std::to_string(value.size()) +
                   (value.size() == 1 ? " element" : " elements");
        }
        case json::value_t::object:
            return value.empty() ? "an empty object" : "an object";
        case json::value_t::binary:
            return "binary data";
        case json::value_t::discarded:
            break;
    }
    return "nothing";
}

std::string quote(std::string_view s) {
    std::string_view cut = s;
    bool truncated = false;
    if (cut.size() > 40) {
        std::size_t n = 40;
        while (n > 0 && isContinuation(static_cast<unsigned char>(cut[n])))
            --n;
        cut = cut.substr(0, n);
        truncated = true;
    }
    std::string out = dumpCompact(json(std::string(cut)));
    if (truncated) out += "...";
    return out;
}

std::string truncateUtf8(std::string_view s, std::size_t maxBytes) {
    if (s.size() <= maxBytes) return std::string(s);
    std::size_t n = maxBytes;
    while (n > 0 && isContinuation(static_cast<unsigned char>(s[n])))
        --n;
    return std::string(s.substr(0, n)) + "...";
}

std::string oneLine(std::string_view s) {
    std::string out;
    out.reserve(s.size());
    for (std::size_t i = 0; i < s.size();) {
        uint32_t cp = 0;
        const std::size_t length = decodeUtf8(s, i, cp);
        if (length == 0) {
            out += '?';
            ++i;
            continue;
        }
        const bool control = cp < 0x20 || (cp >= 0x7F && cp <= 0x9F) || cp == 0x2028 || cp == 0x2029;
        if (control) {
            out += ' ';
        } else {
            out.append(s.substr(i, length));
        }
        i += length;
    }
    return out;
}

TextPosition positionOf(std::string_view text, std::size_t byteOffset) {
    byteOffset = std::min(byteOffset, text.size());
    TextPosition pos;
    std::size_t lineStart = 0;
    for (std::size_t i = 0; i < byteOffset; ++i) {
        if (text[i] == '\n') {
            ++pos.line;
            lineStart = i + 1;
        }
    }
    for (std::size_t i = lineStart; i < byteOffset; ++i) {
        if (!isContinuation(static_cast<unsigned char>(text[i]))) ++pos.column;
    }
    return pos;
}

std::string syntaxError(std::string_view text, std::size_t position, std::string_view what) {
    // nlohmann reports the last byte it read; within a number or literal (1.5e3, tru), point at the
    // start of that token instead.
    std::size_t offset = std::min(position > 0 ? position - 1 : 0, text.size());
    const auto inToken = [](char c) {
        return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '.' ||
               c == '+' || c == '-';
    };
    if (offset < text.size() && inToken(text[offset])) {
        while (offset > 0 && inToken(text[offset - 1]))
            --offset;
    }
    const TextPosition pos = positionOf(text, offset);
    // what: "[json.exception.parse_error.101] parse error at line 1, column 9: syntax error while
    // parsing value - invalid literal; last read: '1} x'; expected end of input"
    std::string_view detail = what;
    if (const std::size_t p = detail.find("parse error"); p != std::string_view::npos) {
        if (const std::size_t colon = detail.find(": ", p); colon != std::string_view::npos) {
            detail = detail.substr(colon + 2);
        }
    } else if (const std::size_t bracket = detail.find("] "); bracket != std::string_view::npos) {
        detail = detail.substr(bracket + 2);
    }
    constexpr std::string_view kPrefix = "syntax error while parsing ";
    std::string context;
    if (detail.substr(0, kPrefix.size()) == kPrefix) {
        const std::string_view rest = detail.substr(kPrefix.size());
        if (const std::size_t dash = rest.find(" - "); dash != std::string_view::npos) {
            context = std::string(rest.substr(0, dash));
            detail = rest.substr(dash + 3);
        }
    }
    std::string message = shortenLastRead(detail);
    if (message.size() > 200) message = truncateUtf8(message, 200);
    if (!context.empty()) message += " (while parsing " + context + ")";
    return "(line " + std::to_string(pos.line) + ", column " + std::to_string(pos.column) +
           ") syntax error: " + message;
}

std::string formatFloat(float f) {
    char buffer[64];
    const auto shortest = std::to_chars(buffer, buffer + sizeof buffer, f);
    if (shortest.ec != std::errc()) return std::to_string(f);
    std::string text(buffer, shortest.ptr);
    if (text.find('e') != std::string::npos) {
        // Prefer 100000 to 1e+05 and 0.0001 to 1e-04 while that stays short.
        const auto fixed = std::to_chars(buffer, buffer + sizeof buffer, f, std::chars_format::fixed);
        if (fixed.ec == std::errc() && fixed.ptr - buffer <= 10) text.assign(buffer, fixed.ptr);
    }
    return text;
}

double roundTripDouble(float f) {
    if (!std::isfinite(f)) return double(f);
    const std::string text = formatFloat(f);
    double d = 0.0;
    const auto result = std::from_chars(text.data(), text.data() + text.size(), d);
    if (result.ec == std::errc() && float(d) == f) return d;
    return double(f);
}

}  // namespace demo::json_text
