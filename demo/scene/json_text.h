// Text helpers for the scene parser's error messages (internal to demo_scene; unit tested).
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <string_view>

namespace demo::json_text {

// Key paths as used in error messages: "camera.near", "objects[2].radius". Keys that are not plain
// identifiers are written quoted: objects[0]["my key"].
std::string keyPath(const std::string& path, std::string_view key);
std::string indexPath(const std::string& path, std::size_t index);

// The value as written after "got" in error messages: -1, 2.5, inf, true, null, the string "60",
// [1,2], an array of 5 elements, an object. Never longer than about 60 bytes.
std::string describe(const nlohmann::json& value);

// A string as a JSON string literal, cut to about 40 bytes.
std::string quote(std::string_view s);

// At most maxBytes bytes of s, cut at a UTF-8 character boundary, followed by "..." when cut.
std::string truncateUtf8(std::string_view s, std::size_t maxBytes);

// s as one printable line of valid UTF-8: control characters and line separators become spaces,
// bytes that are not valid UTF-8 become '?'.
std::string oneLine(std::string_view s);

// 1-based line and column (in characters, i.e. UTF-8 code points) of a byte offset into text.
struct TextPosition {
    std::size_t line = 1;
    std::size_t column = 1;
};
TextPosition positionOf(std::string_view text, std::size_t byteOffset);

// "(line L, column C) syntax error: <detail>" from nlohmann's parse error: position is nlohmann's
// byte count (the offending byte is text[position - 1]), what its exception message.
std::string syntaxError(std::string_view text, std::size_t position, std::string_view what);

// The shortest decimal form of f that reads back as f ("0.1", "100000", "1e-07").
std::string formatFloat(float f);
// A double that a JSON writer prints short and that converts back to exactly f.
double roundTripDouble(float f);

}  // namespace demo::json_text
