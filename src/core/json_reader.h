// Strict reading of JSON objects at the input boundary: every key must be known, every value
// of the right type and inside its documented range. Errors name the source and JSON path.
#pragma once

#include <initializer_list>
#include <istream>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "core/input_error.h"

namespace mg {

// What to do with an object that holds the same key twice. nlohmann keeps the last one
// silently; formats that reject it (traces, docs/trace_format.md) ask for kReject, and the error
// names the JSON path of the repeated key.
enum class DuplicateKeys { kKeepLast, kReject };

// Parses text as JSON; malformed or empty input raises InputError naming `source`.
// Nesting deeper than kMaxJsonDepth is rejected (hostile input guard).
nlohmann::json parse_json_text(const std::string& text, const std::string& source,
                               DuplicateKeys duplicates = DuplicateKeys::kKeepLast);
// Reads a whole stream (at most kMaxInputBytes) and parses it; `source` names it in errors.
nlohmann::json parse_json_stream(std::istream& in, const std::string& source,
                                 DuplicateKeys duplicates = DuplicateKeys::kKeepLast);
// Opens and parses a file (same bounds).
nlohmann::json parse_json_file(const std::string& path, DuplicateKeys duplicates = DuplicateKeys::kKeepLast);

inline constexpr std::size_t kMaxInputBytes = 64u * 1024u * 1024u;
inline constexpr int kMaxJsonDepth = 64;

// A range whose ends may each be excluded. An end with a name is another parameter's value, and
// errors show it as "name = value".
struct NumberRange {
  double lo = 0.0;
  bool lo_open = false;
  std::string lo_name;
  double hi = 0.0;
  bool hi_open = false;
  std::string hi_name;
};

// A view of one JSON object being read, with its path for error messages.
class ObjectReader {
 public:
  ObjectReader(const nlohmann::json& value, std::string source, std::string path);

  // Rejects any key not in `known`.
  void only_keys(std::initializer_list<std::string_view> known) const;
  bool has(std::string_view key) const;

  // Number in [lo, hi]; finite. `required` keys raise when missing.
  double number(std::string_view key, double lo, double hi) const;
  double number_or(std::string_view key, double fallback, double lo, double hi) const;
  // Exclusive lower bound variant: value > lo.
  double positive(std::string_view key, double hi) const;
  double positive_or(std::string_view key, double fallback, double hi) const;
  // Number in `range`; finite. The messages of number() and positive() for their ranges.
  double number_in(std::string_view key, const NumberRange& range) const;
  long long integer(std::string_view key, long long lo, long long hi) const;
  long long integer_or(std::string_view key, long long fallback, long long lo, long long hi) const;
  bool boolean_or(std::string_view key, bool fallback) const;
  std::string string(std::string_view key) const;
  std::string string_or(std::string_view key, const std::string& fallback) const;
  // Sub-object or array; raises when missing or of the wrong type.
  ObjectReader object(std::string_view key) const;
  const nlohmann::json& array(std::string_view key) const;

  const nlohmann::json& value() const { return value_; }
  const std::string& source() const { return source_; }
  std::string path_of(std::string_view key) const { return path_ + "/" + std::string(key); }
  [[noreturn]] void fail(std::string_view key, const std::string& what) const;

 private:
  const nlohmann::json& get(std::string_view key) const;
  const nlohmann::json& value_;
  std::string source_;
  std::string path_;
};

}  // namespace mg
