#include "recording/xml_document.h"

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <pugixml.hpp>

#include "core/input_error.h"

namespace mg {
namespace {

std::string trimmed(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return std::string(s.substr(first, last - first + 1));
}

// Length of the well-formed UTF-8 sequence (RFC 3629: no overlong forms, no surrogates, nothing
// above U+10FFFF) that starts at s[i], or 0 if there is none.
std::size_t utf8_sequence_length(std::string_view s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char b0 = byte(i);
  if (b0 < 0x80) return 1;
  std::size_t n = 0;
  unsigned char lo = 0x80, hi = 0xBF;  // the allowed range of the second byte
  if (b0 >= 0xC2 && b0 <= 0xDF) {
    n = 2;
  } else if (b0 >= 0xE0 && b0 <= 0xEF) {
    n = 3;
    if (b0 == 0xE0) lo = 0xA0;
    if (b0 == 0xED) hi = 0x9F;
  } else if (b0 >= 0xF0 && b0 <= 0xF4) {
    n = 4;
    if (b0 == 0xF0) lo = 0x90;
    if (b0 == 0xF4) hi = 0x8F;
  } else {
    return 0;
  }
  if (i + n > s.size() || byte(i + 1) < lo || byte(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k) {
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  }
  return n;
}

// A recording's strings (benchmark id, obstacle types, ...) travel on into JSON and HTML reports,
// which hold only UTF-8: pugixml converts a declared encoding to UTF-8 but passes the bytes of a
// UTF-8 document through unchecked, so they are checked here, once, at the boundary.
void require_utf8(std::string_view value, const pugi::xml_node& node, std::string_view what,
                  std::string_view text, const std::string& source) {
  for (std::size_t i = 0; i < value.size();) {
    const std::size_t n = utf8_sequence_length(value, i);
    if (n == 0) {
      const auto offset = static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, node.offset_debug()));
      const auto upto = text.substr(0, std::min(offset, text.size()));
      const long line = 1 + std::count(upto.begin(), upto.end(), '\n');
      throw InputError(source, "line " + std::to_string(line) + ", " + std::string(what),
                       "not valid UTF-8 (byte " + std::to_string(i) + ")");
    }
    i += n;
  }
}

// Recursion is bounded by kMaxXmlDepth, so a hostile file cannot exhaust the stack here.
XmlElement convert(const pugi::xml_node& node, int depth, std::string_view text_in, const std::string& source) {
  if (depth > kMaxXmlDepth) {
    throw InputError(source, std::string("element <") + node.name() + ">",
                     "nesting deeper than " + std::to_string(kMaxXmlDepth) + " levels");
  }
  XmlElement e;
  e.name = node.name();
  require_utf8(e.name, node, "element name", text_in, source);
  for (const pugi::xml_attribute& a : node.attributes()) {
    require_utf8(a.name(), node, std::string("an attribute name of <") + e.name + ">", text_in, source);
    require_utf8(a.value(), node, std::string("attribute ") + a.name() + " of <" + e.name + ">", text_in, source);
    e.attributes.emplace_back(a.name(), a.value());
  }
  std::string text;
  for (const pugi::xml_node& c : node.children()) {
    if (c.type() == pugi::node_element) {
      e.children.push_back(convert(c, depth + 1, text_in, source));
    } else if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) {
      text += c.value();
    }
  }
  require_utf8(text, node, std::string("the text of <") + e.name + ">", text_in, source);
  e.text = trimmed(text);
  return e;
}

}  // namespace

const std::string* XmlElement::attribute(std::string_view key) const {
  for (const auto& [k, v] : attributes) {
    if (k == key) return &v;
  }
  return nullptr;
}

const XmlElement* XmlElement::first(std::string_view child) const {
  for (const XmlElement& c : children) {
    if (c.name == child) return &c;
  }
  return nullptr;
}

std::vector<const XmlElement*> XmlElement::all(std::string_view child) const {
  std::vector<const XmlElement*> out;
  for (const XmlElement& c : children) {
    if (c.name == child) out.push_back(&c);
  }
  return out;
}

XmlElement parse_xml_strict(std::string_view text, const std::string& source) {
  // pugixml does not expand custom entities, but a recording has no use for a DTD at all:
  // refusing it outright keeps the reader's behaviour independent of that detail.
  if (text.find("<!DOCTYPE") != std::string_view::npos || text.find("<!ENTITY") != std::string_view::npos) {
    throw InputError(source, "document", "DOCTYPE/ENTITY declarations are not accepted");
  }
  pugi::xml_document doc;
  const pugi::xml_parse_result r = doc.load_buffer(text.data(), text.size(), pugi::parse_default);
  if (!r) {
    const auto upto = text.substr(0, std::min<std::size_t>(static_cast<std::size_t>(r.offset), text.size()));
    const long line = 1 + std::count(upto.begin(), upto.end(), '\n');
    throw InputError(source, "line " + std::to_string(line) + " (offset " + std::to_string(r.offset) + ")",
                     std::string("malformed XML: ") + r.description());
  }
  const pugi::xml_node root = doc.document_element();
  if (!root) throw InputError(source, "document", "no root element");
  return convert(root, 1, text, source);
}

XmlElement load_xml_strict(const std::string& path) {
  std::error_code ec;
  const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
  if (ec) throw InputError(path, "file", "cannot read: " + ec.message());
  if (bytes > kMaxRecordingBytes) {
    throw InputError(path, "file", "file of " + std::to_string(bytes) + " bytes exceeds the 256 MiB cap");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "file", "cannot open");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_xml_strict(text.str(), path);
}

}  // namespace mg
