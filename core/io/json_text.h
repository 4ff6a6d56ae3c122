#pragma once
// JSON from files and options (op lists, render and event scripts): the whole text or a one-line
// usage error, and numbers taken only where they fit the type they become.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <functional>
#include <string>

namespace gps {

/// How deep JSON from a file may nest (arrays and objects within each other): deeper text is refused
/// while it is read, before it costs memory or a reader's recursion.
inline constexpr size_t kMaxJsonDepth = 64;

/// Parses `text` as one JSON value. Throws a usage error "SOURCE: ..." (or without "SOURCE: " where
/// it is empty) for a NUL byte or a syntax error, naming its byte, and for a number beyond a double's
/// range, naming the element as a path from the top, e.g. "ops[3].cuts" with `top_name` "ops" for a
/// top-level array, or "renders[0].level" for an object.
nlohmann::json parse_json(const std::string& text, const std::string& source, const std::string& top_name = "");

/// Receives a top-level array's elements one at a time: its index and the element, to keep or drop.
using JsonElementSink = std::function<void(size_t index, nlohmann::json&& element)>;

/// Parses `text` as parse_json does where it is a JSON array, but hands each element to `sink` as soon
/// as it is read, so that only one element is held at a time (an op list of 100 MB is never a DOM of
/// gigabytes). Returns false, having called `sink` for nothing, where the text is valid JSON but not an
/// array; throws as parse_json does otherwise (and rethrows what `sink` throws).
bool parse_json_array(const std::string& text, const std::string& source, const std::string& top_name,
                      const JsonElementSink& sink);

/// `value` as an integer from `lo` to `hi`; else throws a usage error "must be an integer from LO
/// to HI, got X" (1.9, 4294967297 and "1" are refused, never truncated, wrapped or converted).
long long json_integer(const nlohmann::json& value, long long lo, long long hi);

/// `value` as a finite number; else throws a usage error "must be a finite number, got X".
double json_number(const nlohmann::json& value);

/// A JSON value as a message shows it: a number as written, anything else by its kind ("a string").
std::string json_shown(const nlohmann::json& value);

/// What a nlohmann::json exception says, in its words without its "[json.exception...]" tag, cut to
/// one short line.
std::string json_error_words(const nlohmann::json::exception& e);

}  // namespace gps
