#pragma once
/// Values quoted in the model reader's messages. Every quote is bounded in length and depth: a
/// message must stay a sentence whatever the document holds (a string of a megabyte, arrays nested a
/// million deep).

#include <span>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace saasgaps::io {

/// A number as JSON writes it (shortest round trip, 1.0 stays 1.0), and inf or nan, which JSON
/// cannot write.
std::string format_number(double v);

/// A string as a JSON string literal; long ones are cut, invalid UTF-8 is replaced.
std::string quote_string(std::string_view text);

/// The value as (bounded) JSON text, for quoting in a message.
std::string quote(const nlohmann::json& value);

/// "the string \"1\"", "the array [1, 2]", "null": what a value of the wrong type was.
std::string describe(const nlohmann::json& value);

/// "a, b, c": a list of names for a message.
std::string join(std::span<const std::string_view> names);

}  // namespace saasgaps::io
