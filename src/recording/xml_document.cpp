#include "recording/xml_document.h"

#include <algorithm>
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

// Recursion is bounded by kMaxXmlDepth, so a hostile file cannot exhaust the stack here.
XmlElement convert(const pugi::xml_node& node, int depth, const std::string& source) {
  if (depth > kMaxXmlDepth) {
    throw InputError(source, std::string("element <") + node.name() + ">",
                     "nesting deeper than " + std::to_string(kMaxXmlDepth) + " levels");
  }
  XmlElement e;
  e.name = node.name();
  for (const pugi::xml_attribute& a : node.attributes()) e.attributes.emplace_back(a.name(), a.value());
  std::string text;
  for (const pugi::xml_node& c : node.children()) {
    if (c.type() == pugi::node_element) {
      e.children.push_back(convert(c, depth + 1, source));
    } else if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) {
      text += c.value();
    }
  }
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
  return convert(root, 1, source);
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
