// The strict XML adapter (src/recording/xml_document.h): a plain element tree from good XML, and
// one InputError line naming the source for every hostile document.
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "recording/xml_document.h"

namespace mg {
namespace {

std::string xml_error_of(const std::string& text) {
  try {
    parse_xml_strict(text, "doc.xml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(XmlDocument, ReadsElementsAttributesAndTrimmedText) {
  const XmlElement root = parse_xml_strict("<a k=\"v\"><b> 1.5 </b><b>2</b><c/></a>", "doc.xml");
  EXPECT_EQ(root.name, "a");
  ASSERT_NE(root.attribute("k"), nullptr);
  EXPECT_EQ(*root.attribute("k"), "v");
  EXPECT_EQ(root.attribute("missing"), nullptr);
  ASSERT_EQ(root.all("b").size(), 2u);
  EXPECT_EQ(root.first("b")->text, "1.5");
  EXPECT_NE(root.first("c"), nullptr);
  EXPECT_EQ(root.first("d"), nullptr);
}

TEST(XmlDocument, RefusesEntityDeclarationsBillionLaughs) {
  const std::string laughs =
      "<?xml version=\"1.0\"?><!DOCTYPE lolz [<!ENTITY lol \"lol\"><!ENTITY lol2 \"&lol;&lol;&lol;\">]><lolz>&lol2;</lolz>";
  EXPECT_EQ(xml_error_of(laughs), "doc.xml: document: DOCTYPE/ENTITY declarations are not accepted");
}

TEST(XmlDocument, RefusesMalformedAndTruncatedXmlInOneLine) {
  for (const std::string text : {"<a><b></a>", "<a><b>1</b>", "", "not xml at all", "<a>\x01</a"}) {
    const std::string e = xml_error_of(text);
    EXPECT_EQ(e.rfind("doc.xml: ", 0), 0u) << text;
    EXPECT_EQ(e.find('\n'), std::string::npos) << text;
  }
}

TEST(XmlDocument, RefusesBytesThatAreNotUtf8NamingTheLineAndTheAttribute) {
  // 0xA4 alone (what a Latin-1 euro sign leaves in a document read as UTF-8), a truncated
  // sequence, an overlong '/', a UTF-16 surrogate: each would otherwise reach the JSON reports.
  for (const std::string bad : {"\xA4", "\xC3", "\xC0\xAF", "\xED\xA0\x80"}) {
    EXPECT_EQ(xml_error_of("<a>\n<b id=\"x" + bad + "\"/></a>"),
              "doc.xml: line 2, attribute id of <b>: not valid UTF-8 (byte 1)")
        << bad;
    EXPECT_EQ(xml_error_of("<a>t" + bad + "</a>"), "doc.xml: line 1, the text of <a>: not valid UTF-8 (byte 1)") << bad;
  }
  const XmlElement ok = parse_xml_strict("<a id=\"\xE2\x82\xAC \xF0\x9F\x9A\x97\">\xC3\xA4</a>", "doc.xml");
  EXPECT_EQ(*ok.attribute("id"), "\xE2\x82\xAC \xF0\x9F\x9A\x97");
  EXPECT_EQ(ok.text, "\xC3\xA4");
}

TEST(XmlDocument, RefusesNestingDeeperThanTheLimit) {
  std::string deep;
  for (int i = 0; i < kMaxXmlDepth + 2; ++i) deep += "<a>";
  for (int i = 0; i < kMaxXmlDepth + 2; ++i) deep += "</a>";
  EXPECT_NE(xml_error_of(deep).find("nesting deeper than"), std::string::npos);
}

TEST(XmlDocument, RefusesAFileOverTheCapBeforeReadingIt) {
  const auto path = std::filesystem::temp_directory_path() / ("mg_huge_" + std::to_string(::getpid()) + ".xml");
  { std::ofstream(path) << "<a/>"; }
  std::filesystem::resize_file(path, kMaxRecordingBytes + 1);  // sparse: costs no disk
  try {
    load_xml_strict(path.string());
    ADD_FAILURE() << "a file over the cap was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("exceeds the 256 MiB cap"), std::string::npos);
  }
  std::filesystem::remove(path);
}

TEST(XmlDocument, RefusesAMissingFile) {
  EXPECT_THROW(load_xml_strict("/nonexistent/recording.xml"), InputError);
}

}  // namespace
}  // namespace mg
