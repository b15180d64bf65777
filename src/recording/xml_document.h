// Strict loading of an XML recording: the one place that touches pugixml. It
// refuses oversized files before reading them, DOCTYPE/ENTITY declarations (entity expansion
// attacks), nesting deeper than kMaxXmlDepth, malformed or truncated XML and names, attribute
// values or text that are not valid UTF-8, each as one
// mg::InputError line naming the file, and hands the rest on as a plain element tree, so that
// no other file depends on pugixml.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mg {

inline constexpr std::uintmax_t kMaxRecordingBytes = 256ull * 1024 * 1024;
inline constexpr int kMaxXmlDepth = 32;

struct XmlElement {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;
  std::string text;  // the element's own character data, trimmed
  std::vector<XmlElement> children;

  // The attribute's value, or nullptr.
  const std::string* attribute(std::string_view key) const;
  // The first child named `child`, or nullptr.
  const XmlElement* first(std::string_view child) const;
  // Every child named `child`, in document order.
  std::vector<const XmlElement*> all(std::string_view child) const;
};

// Parses `text` and returns its root element; `source` names it in errors.
XmlElement parse_xml_strict(std::string_view text, const std::string& source);
// Checks the size cap before reading, then parses as above.
XmlElement load_xml_strict(const std::string& path);

}  // namespace mg
