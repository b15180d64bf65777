#include "core/json_reader.h"

#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <vector>

namespace mg {
namespace {

std::string type_name(const nlohmann::json& v) {
  if (v.is_number()) return "a number";
  return std::string("a") + (v.is_object() || v.is_array() ? "n " : " ") + v.type_name();
}

std::string format_number(double x) {
  std::ostringstream out;
  out.precision(10);
  out << x;
  return out.str();
}

// Depth guard: nlohmann parses recursively; reject absurd nesting before it hurts.
void check_depth(const std::string& text, const std::string& source) {
  int depth = 0;
  bool in_string = false;
  bool escaped = false;
  for (char c : text) {
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') in_string = true;
    else if (c == '{' || c == '[') {
      if (++depth > kMaxJsonDepth)
        throw InputError(source, "", "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    } else if (c == '}' || c == ']') {
      --depth;
    }
  }
}

// Parser callback that rejects a repeated key in any object. It keeps, per open container, the
// keys seen (objects) or the element index (arrays), which is also the JSON path of the error.
class UniqueKeys {
 public:
  explicit UniqueKeys(const std::string& source) : source_(source) {}
  bool operator()(int /*depth*/, nlohmann::json::parse_event_t event, const nlohmann::json& parsed) {
    using E = nlohmann::json::parse_event_t;
    switch (event) {
      case E::object_start: frames_.push_back({false, 0, {}, {}}); break;
      case E::array_start: frames_.push_back({true, 0, {}, {}}); break;
      case E::key: {
        Frame& f = frames_.back();
        f.key = parsed.get<std::string>();
        if (!f.keys.insert(f.key).second) throw InputError(source_, path(), "duplicate key '" + f.key + "'");
        break;
      }
      case E::object_end:
      case E::array_end:
        frames_.pop_back();
        element_done();
        break;
      case E::value: element_done(); break;
    }
    return true;
  }

 private:
  struct Frame {
    bool array;
    std::size_t index;
    std::string key;
    std::set<std::string> keys;
  };
  void element_done() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
  }
  std::string path() const {
    std::string p;
    for (const auto& f : frames_) p += "/" + (f.array ? std::to_string(f.index) : f.key);
    return p;
  }
  const std::string& source_;
  std::vector<Frame> frames_;
};

}  // namespace

nlohmann::json parse_json_text(const std::string& text, const std::string& source, DuplicateKeys duplicates) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw InputError(source, "", "empty input, expected a JSON object");
  check_depth(text, source);
  try {
    if (duplicates == DuplicateKeys::kReject) return nlohmann::json::parse(text, UniqueKeys(source));
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    std::string what = e.what();
    if (auto pos = what.find("parse error"); pos != std::string::npos) what = what.substr(pos);
    throw InputError(source, "", "malformed JSON (" + what + ")");
  } catch (const nlohmann::json::out_of_range&) {
    // A number literal beyond the range of a double (e.g. 2e308).
    throw InputError(source, "", "number out of range of a double");
  } catch (const nlohmann::json::exception& e) {
    throw InputError(source, "", std::string("invalid JSON (") + e.what() + ")");
  }
}

nlohmann::json parse_json_stream(std::istream& in, const std::string& source, DuplicateKeys duplicates) {
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxInputBytes)
      throw InputError(source, "", "input larger than " + std::to_string(kMaxInputBytes / (1024 * 1024)) + " MiB");
  }
  return parse_json_text(text, source, duplicates);
}

nlohmann::json parse_json_file(const std::string& path, DuplicateKeys duplicates) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open file");
  return parse_json_stream(in, path, duplicates);
}

ObjectReader::ObjectReader(const nlohmann::json& value, std::string source, std::string path)
    : value_(value), source_(std::move(source)), path_(std::move(path)) {
  if (!value_.is_object()) throw InputError(source_, path_, "must be a JSON object, got " + type_name(value_));
}

void ObjectReader::fail(std::string_view key, const std::string& what) const {
  throw InputError(source_, path_of(key), what);
}

void ObjectReader::only_keys(std::initializer_list<std::string_view> known) const {
  for (const auto& item : value_.items()) {
    bool found = false;
    for (auto k : known) found = found || (k == item.key());
    if (!found) fail(item.key(), "unknown key");
  }
}

bool ObjectReader::has(std::string_view key) const { return value_.contains(std::string(key)); }

const nlohmann::json& ObjectReader::get(std::string_view key) const {
  auto it = value_.find(std::string(key));
  if (it == value_.end()) fail(key, "missing required key");
  return *it;
}

double ObjectReader::number(std::string_view key, double lo, double hi) const {
  const auto& v = get(key);
  if (!v.is_number()) fail(key, "must be a number, got " + type_name(v));
  const double x = v.get<double>();
  if (!std::isfinite(x)) fail(key, "must be finite");
  if (x < lo || x > hi)
    fail(key, "must be in [" + format_number(lo) + ", " + format_number(hi) + "], got " + format_number(x));
  return x;
}

double ObjectReader::number_or(std::string_view key, double fallback, double lo, double hi) const {
  return has(key) ? number(key, lo, hi) : fallback;
}

double ObjectReader::positive(std::string_view key, double hi) const {
  const double x = number(key, -std::numeric_limits<double>::max(), std::numeric_limits<double>::max());
  if (!(x > 0.0)) fail(key, "must be > 0, got " + format_number(x));
  if (x > hi) fail(key, "must be in (0, " + format_number(hi) + "], got " + format_number(x));
  return x;
}

double ObjectReader::positive_or(std::string_view key, double fallback, double hi) const {
  return has(key) ? positive(key, hi) : fallback;
}

double ObjectReader::number_in(std::string_view key, const NumberRange& range) const {
  const double x = number(key, -std::numeric_limits<double>::max(), std::numeric_limits<double>::max());
  const auto end = [](double v, const std::string& name) { return name.empty() ? format_number(v) : name + " = " + format_number(v); };
  const std::string interval = std::string(range.lo_open ? "(" : "[") + end(range.lo, range.lo_name) + ", " +
                               end(range.hi, range.hi_name) + (range.hi_open ? ")" : "]");
  const bool below_lo = range.lo_open ? !(x > range.lo) : x < range.lo;
  const bool above_hi = range.hi_open ? !(x < range.hi) : x > range.hi;
  // An open lower end alone reads "> lo", as positive() has always said of a value at or below 0.
  if (below_lo && range.lo_open && range.lo_name.empty()) fail(key, "must be > " + format_number(range.lo) + ", got " + format_number(x));
  if (below_lo || above_hi) fail(key, "must be in " + interval + ", got " + format_number(x));
  return x;
}

long long ObjectReader::integer(std::string_view key, long long lo, long long hi) const {
  const auto& v = get(key);
  if (!v.is_number_integer()) fail(key, "must be an integer, got " + type_name(v));
  if (v.is_number_unsigned() && v.get<unsigned long long>() > static_cast<unsigned long long>(hi))
    fail(key, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  const long long x = v.get<long long>();
  if (x < lo || x > hi)
    fail(key, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + std::to_string(x));
  return x;
}

long long ObjectReader::integer_or(std::string_view key, long long fallback, long long lo, long long hi) const {
  return has(key) ? integer(key, lo, hi) : fallback;
}

bool ObjectReader::boolean_or(std::string_view key, bool fallback) const {
  if (!has(key)) return fallback;
  const auto& v = get(key);
  if (!v.is_boolean()) fail(key, "must be true or false, got " + type_name(v));
  return v.get<bool>();
}

std::string ObjectReader::string(std::string_view key) const {
  const auto& v = get(key);
  if (!v.is_string()) fail(key, "must be a string, got " + type_name(v));
  return v.get<std::string>();
}

std::string ObjectReader::string_or(std::string_view key, const std::string& fallback) const {
  return has(key) ? string(key) : fallback;
}

ObjectReader ObjectReader::object(std::string_view key) const {
  const auto& v = get(key);
  if (!v.is_object()) fail(key, "must be a JSON object, got " + type_name(v));
  return ObjectReader(v, source_, path_of(key));
}

const nlohmann::json& ObjectReader::array(std::string_view key) const {
  const auto& v = get(key);
  if (!v.is_array()) fail(key, "must be an array, got " + type_name(v));
  return v;
}

}  // namespace mg
