#include "prism/core/printable_text.h"

#include <string>

#include <gtest/gtest.h>

namespace prism {
namespace {

TEST(PrintableText, PrintableAsciiAndTabPassUnchanged) {
  EXPECT_EQ(printable_text("scene.glb: buffer 0\tok ~!\\"), "scene.glb: buffer 0\tok ~!\\");
}

TEST(PrintableText, ControlBytesAndDelAreEscaped) {
  EXPECT_EQ(printable_text("a\nb\rc\x1b[31md\x7f"), "a\\x0Ab\\x0Dc\\x1B[31md\\x7F");
  EXPECT_EQ(printable_text(std::string("x\0y", 3)), "x\\x00y");
}

TEST(PrintableText, WellFormedUtf8PassesUnchanged) {
  // é (2 bytes), € (3 bytes), 😀 (4 bytes), U+10FFFF is the last code point.
  const std::string text = "caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80 \xF4\x8F\xBF\xBF";
  EXPECT_EQ(printable_text(text), text);
}

TEST(PrintableText, IllFormedUtf8IsEscapedByteByByte) {
  EXPECT_EQ(printable_text("\xFF\xFE"), "\\xFF\\xFE");                 // never in UTF-8
  EXPECT_EQ(printable_text("\xC0\xAF"), "\\xC0\\xAF");                 // overlong '/'
  EXPECT_EQ(printable_text("\xE0\x80\xAF"), "\\xE0\\x80\\xAF");        // overlong, 3 bytes
  EXPECT_EQ(printable_text("\xED\xA0\x80"), "\\xED\\xA0\\x80");        // surrogate U+D800
  EXPECT_EQ(printable_text("\xF4\x90\x80\x80"), "\\xF4\\x90\\x80\\x80");  // above U+10FFFF
  EXPECT_EQ(printable_text("\xC3"), "\\xC3");                          // truncated at the end
  EXPECT_EQ(printable_text("\xE2\x82z"), "\\xE2\\x82z");               // truncated, then ASCII
  EXPECT_EQ(printable_text("\x80x"), "\\x80x");                        // lone continuation byte
}

TEST(PrintableText, C1ControlsAreEscaped) {
  EXPECT_EQ(printable_text("a\xC2\x85z"), "a\\xC2\\x85z");  // U+0085 NEXT LINE
  EXPECT_EQ(printable_text("\xC2\xA0"), "\xC2\xA0");        // U+00A0 is printable (no-break space)
}

}  // namespace
}  // namespace prism
