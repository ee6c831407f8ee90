#pragma once
// Text from input files (names, messages that quote their bytes) made safe to print on a
// terminal or in a log: an error about a binary file must not echo its bytes.
#include <string>
#include <string_view>

namespace prism {

// `text` with every byte that is not part of a printable character written as `\xNN`
// (two upper-case hex digits): C0 controls except tab, DEL, the C1 controls U+0080–U+009F,
// and every byte of a sequence that is not well-formed UTF-8 (Unicode 15.0 §3.9, Table
// 3-7: no overlong forms, no surrogates, nothing above U+10FFFF). Well-formed printable
// UTF-8 (a non-ASCII file name) passes unchanged; a newline is escaped too, so a message
// stays one line.
std::string printable_text(std::string_view text);

}  // namespace prism
