#include "prism/scene/radiance_hdr.h"

#include <algorithm>
#include <climits>
#include <cstring>
#include <string>

#include <fmt/format.h>

#include "prism/core/error.h"

namespace prism {
namespace {

[[noreturn]] void fail(std::string_view name, std::string_view why) {
  throw IoError(fmt::format("cannot read image '{}': {}", name, why));
}

// The bytes from `pos` up to the next '\n' (or the end), and pos moved past it.
std::string_view next_line(std::span<const unsigned char> bytes, std::size_t& pos) {
  const auto* begin = reinterpret_cast<const char*>(bytes.data()) + pos;
  const std::size_t left = bytes.size() - pos;
  const void* newline = std::memchr(begin, '\n', left);
  const std::size_t length = newline ? static_cast<std::size_t>(static_cast<const char*>(newline) - begin) : left;
  pos += newline ? length + 1 : length;
  return {begin, length};
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r'; }

// strtol's reading of a decimal number at the start of `text` (leading white space, a sign,
// digits; 0 without digits), saturating at the range of long; `text` moves past it.
long parse_long(std::string_view& text) {
  std::size_t i = 0;
  while (i < text.size() && is_space(text[i])) ++i;
  bool negative = false;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) negative = text[i++] == '-';
  const std::size_t digits_start = i;
  long value = 0;
  for (; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i) {
    const int digit = text[i] - '0';
    value = value > (LONG_MAX - digit) / 10 ? LONG_MAX : value * 10 + digit;
  }
  if (i == digits_start) return 0;  // strtol consumes nothing then
  text.remove_prefix(i);
  return negative ? -value : value;
}

// Reads bytes in order; running past the end is a truncated file.
class ByteReader {
 public:
  ByteReader(std::span<const unsigned char> bytes, std::size_t pos, std::string_view name)
      : bytes_(bytes), pos_(pos), name_(name) {}
  std::uint8_t byte() {
    if (pos_ >= bytes_.size()) fail(name_, "the file is truncated");
    return bytes_[pos_++];
  }
  void copy(std::uint8_t* out, std::size_t n) {
    if (n > bytes_.size() - pos_) fail(name_, "the file is truncated");
    std::memcpy(out, bytes_.data() + pos_, n);
    pos_ += n;
  }

 private:
  std::span<const unsigned char> bytes_;
  std::size_t pos_;
  std::string_view name_;
};

}  // namespace

RadianceHeader read_radiance_header(std::span<const unsigned char> bytes, std::string_view name) {
  std::size_t pos = 0;
  const std::string_view magic = next_line(bytes, pos);
  if (magic != "#?RADIANCE" && magic != "#?RGBE") fail(name, "not a Radiance picture (no #?RADIANCE line)");
  bool rgbe = false;
  for (;;) {  // variables up to the empty line that ends the header
    if (pos >= bytes.size()) fail(name, "the header has no end");
    const std::string_view line = next_line(bytes, pos);
    if (line.empty()) break;
    if (line == "FORMAT=32-bit_rle_rgbe") rgbe = true;
  }
  if (!rgbe) fail(name, "unsupported Radiance format (FORMAT=32-bit_rle_rgbe expected)");
  const std::string_view line = next_line(bytes, pos);
  const auto unsupported_layout = [&] {
    fail(name,
         fmt::format("unsupported Radiance resolution line '{}' (-Y height +X width expected)", line.substr(0, 40)));
  };
  std::string_view rest = line;  // what is left to parse of the line
  if (!rest.starts_with("-Y ")) unsupported_layout();
  rest.remove_prefix(3);
  RadianceHeader h;
  h.height = parse_long(rest);
  while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
  if (!rest.starts_with("+X ")) unsupported_layout();
  rest.remove_prefix(3);
  h.width = parse_long(rest);
  h.data_offset = pos;
  return h;
}

std::vector<std::uint8_t> read_radiance_texels(std::span<const unsigned char> bytes, const RadianceHeader& header,
                                               std::string_view name) {
  const auto width = static_cast<std::size_t>(header.width), height = static_cast<std::size_t>(header.height);
  // The fewest bytes any file of this size holds: 4 per texel flat; run-length, a scanline's
  // marker and, per component, a run (2 bytes) per 127 texels. A header that claims more
  // texels than its file could hold is refused before the texels are allocated (a 40-byte
  // file can claim 32768² texels: 4 GiB).
  const bool run_length = width >= 8 && width < 32768;
  const std::size_t least = run_length ? height * (4 + 8 * ((width + 126) / 127)) : width * height * 4;
  if (bytes.size() < header.data_offset || bytes.size() - header.data_offset < least)
    fail(name, fmt::format("the file is truncated ({} bytes of texels for {}x{}, at least {} needed)",
                           bytes.size() - std::min(bytes.size(), header.data_offset), width, height, least));
  std::vector<std::uint8_t> texels(width * height * 4);
  ByteReader in(bytes, header.data_offset, name);
  // Flat texels from texel `first` to the end of the image.
  const auto flat = [&](std::size_t first) { in.copy(texels.data() + 4 * first, texels.size() - 4 * first); };
  if (!run_length) {  // too narrow or too wide to be run-length encoded
    flat(0);
    return texels;
  }
  for (std::size_t y = 0; y < height; ++y) {
    std::uint8_t* row = texels.data() + 4 * width * y;
    const std::uint8_t c1 = in.byte(), c2 = in.byte(), high = in.byte();
    if (c1 != 2 || c2 != 2 || (high & 0x80)) {
      // Not a run-length scanline: flat texels from here on, which stb_image (and so Prism
      // before it read these files itself) puts from the image's first texel.
      texels[0] = c1, texels[1] = c2, texels[2] = high, texels[3] = in.byte();
      flat(1);
      return texels;
    }
    const std::size_t length = static_cast<std::size_t>(high) << 8 | in.byte();
    if (length != width)
      fail(name, fmt::format("corrupt run-length data (a scanline of {} texels in an image {} wide)", length, width));
    for (std::size_t k = 0; k < 4; ++k) {  // each component's runs and dumps in turn
      for (std::size_t x = 0; x < width;) {
        std::size_t count = in.byte();
        const bool run = count > 128;
        if (run) count -= 128;
        if (count > width - x) fail(name, "corrupt run-length data (a run past the end of its scanline)");
        if (run) {
          const std::uint8_t value = in.byte();
          for (std::size_t i = 0; i < count; ++i) row[4 * (x + i) + k] = value;
        } else {
          for (std::size_t i = 0; i < count; ++i) row[4 * (x + i) + k] = in.byte();
        }
        x += count;
      }
    }
  }
  return texels;
}

}  // namespace prism
