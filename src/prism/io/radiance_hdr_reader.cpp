#include "prism/io/radiance_hdr_reader.h"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstring>
#include <string>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/io/radiance_rle.h"

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

std::string_view trim(std::string_view text) {
  while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
  return text;
}

// The value of header line `line` if it sets variable `prefix` ("EXPOSURE="), trimmed.
std::optional<std::string_view> variable(std::string_view line, std::string_view prefix) {
  if (!line.starts_with(prefix)) return std::nullopt;
  return trim(line.substr(prefix.size()));
}

// Exactly N finite numbers separated by white space (as Radiance's printf writes them), or
// nothing.
template <std::size_t N>
std::optional<std::array<double, N>> parse_numbers(std::string_view text) {
  std::array<double, N> values{};
  for (std::size_t i = 0; i < N; ++i) {
    text = trim(text);
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), values[i]);
    if (ec != std::errc() || !std::isfinite(values[i])) return std::nullopt;
    text.remove_prefix(static_cast<std::size_t>(end - text.data()));
    if (!text.empty() && !is_space(text.front())) return std::nullopt;  // "2x"
  }
  if (!trim(text).empty()) return std::nullopt;
  return values;
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
  RadianceHeader h;
  bool format = false;
  int line_number = 1;
  const auto bad_line = [&](std::string_view line, std::string_view why) {
    fail(name, fmt::format("header line {} '{}' {}", line_number, line.substr(0, 80), why));
  };
  for (;;) {  // variables up to the empty line that ends the header
    if (pos >= bytes.size()) fail(name, "the header has no end");
    const std::string_view line = next_line(bytes, pos);
    ++line_number;
    if (line.empty()) break;
    if (const auto value = variable(line, "FORMAT=")) {
      format = *value == "32-bit_rle_rgbe" || *value == "32-bit_rle_xyze";
      h.xyz = *value == "32-bit_rle_xyze";
    } else if (const auto exposure = variable(line, "EXPOSURE=")) {
      const auto e = parse_numbers<1>(*exposure);
      if (!e || !((*e)[0] > 0.0)) bad_line(line, "is no exposure (a positive number expected)");
      h.exposure *= (*e)[0];
    } else if (const auto correction = variable(line, "COLORCORR=")) {
      const auto c = parse_numbers<3>(*correction);
      if (!c || !((*c)[0] > 0.0 && (*c)[1] > 0.0 && (*c)[2] > 0.0))
        bad_line(line, "is no colour correction (three positive numbers expected)");
      for (std::size_t k = 0; k < 3; ++k) h.color_correction[k] *= (*c)[k];
    } else if (const auto primaries = variable(line, "PRIMARIES=")) {
      const auto p = parse_numbers<8>(*primaries);
      if (!p) bad_line(line, "is no primaries (eight numbers expected: red, green, blue and white x y)");
      if (std::all_of(p->begin(), p->end(), [](double v) { return v == 0.0; })) continue;  // Photoshop's "none"
      const color::Primaries read{{(*p)[0], (*p)[1]}, {(*p)[2], (*p)[3]}, {(*p)[4], (*p)[5]}, {(*p)[6], (*p)[7]}};
      try {
        color::validate_primaries(read);
      } catch (const Error& e) {
        bad_line(line, fmt::format("names no RGB space ({})", e.what()));
      }
      h.primaries = read;
    }
  }
  if (!format)
    fail(name, "unsupported Radiance format (FORMAT=32-bit_rle_rgbe or FORMAT=32-bit_rle_xyze expected)");
  const std::string_view line = next_line(bytes, pos);
  const auto unsupported_layout = [&] {
    fail(name, fmt::format("unsupported Radiance resolution line '{}' (±Y height ±X width, or ±X width ±Y height, "
                           "expected)",
                           line.substr(0, 40)));
  };
  // Two axes, each a sign, X or Y, and a count: the first is the one scanlines step along,
  // the second the one each scanline runs along. Y points up, so "-Y" starts at the top.
  std::string_view rest = line;  // what is left to parse of the line
  char axes[2] = {}, signs[2] = {};
  long counts[2] = {};
  for (int i = 0; i < 2; ++i) {
    while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
    if (rest.size() < 3 || (rest[0] != '-' && rest[0] != '+') || (rest[1] != 'X' && rest[1] != 'Y') || rest[2] != ' ')
      unsupported_layout();
    signs[i] = rest[0], axes[i] = rest[1];
    rest.remove_prefix(3);
    counts[i] = parse_long(rest);
  }
  if (axes[0] == axes[1]) unsupported_layout();
  h.columns = axes[0] == 'X';
  h.width = h.columns ? counts[0] : counts[1];
  h.height = h.columns ? counts[1] : counts[0];
  h.bottom_up = signs[h.columns ? 1 : 0] == '+';
  h.right_to_left = signs[h.columns ? 0 : 1] == '-';
  h.data_offset = pos;
  return h;
}

namespace {

// The texels in the file's order: `scanlines` scanlines of `width` texels each.
std::vector<std::uint8_t> read_scanlines(std::span<const unsigned char> bytes, const RadianceHeader& header,
                                         std::size_t width, std::size_t height, std::string_view name) {
  // The fewest bytes any file of this size holds: 4 per texel flat; run-length, a scanline's
  // marker and, per component, a run (2 bytes) per 127 texels. A header that claims more
  // texels than its file could hold is refused before the texels are allocated (a 40-byte
  // file can claim 32768² texels: 4 GiB).
  const bool run_length = radiance_scanline_is_run_length(width);
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
      fail(name, fmt::format("corrupt run-length data (a scanline of {} texels, not {})", length, width));
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

}  // namespace

std::vector<std::uint8_t> read_radiance_texels(std::span<const unsigned char> bytes, const RadianceHeader& header,
                                               std::string_view name) {
  const auto width = static_cast<std::size_t>(header.width), height = static_cast<std::size_t>(header.height);
  if (!header.columns && !header.bottom_up && !header.right_to_left)  // "-Y H +X W", the standard order
    return read_scanlines(bytes, header, width, height, name);
  const std::size_t scanline_length = header.columns ? height : width;
  const std::vector<std::uint8_t> file = read_scanlines(bytes, header, scanline_length,
                                                        header.columns ? width : height, name);
  std::vector<std::uint8_t> texels(file.size());
  for (std::size_t t = 0; t < width * height; ++t) {
    const std::size_t scanline = t / scanline_length, along = t % scanline_length;
    std::size_t x = header.columns ? scanline : along, y = header.columns ? along : scanline;
    if (header.right_to_left) x = width - 1 - x;
    if (header.bottom_up) y = height - 1 - y;
    std::memcpy(texels.data() + 4 * (y * width + x), file.data() + 4 * t, 4);
  }
  return texels;
}

color::ColorSpace radiance_color_space(const RadianceHeader& header, std::string_view name) {
  if (header.xyz) return color::xyz_space("xyz-e", color::kWhiteE);
  if (header.primaries) return color::make_color_space(std::string(name), *header.primaries);  // validated
  return color::color_space("srgb");
}

bool radiance_texels_scaled(const RadianceHeader& header) {
  return header.exposure != 1.0 || header.color_correction != std::array<double, 3>{1.0, 1.0, 1.0};
}

Vec3d radiance_texel_factors(const RadianceHeader& header) {
  const auto& c = header.color_correction;
  return {1.0 / (header.exposure * c[0]), 1.0 / (header.exposure * c[1]), 1.0 / (header.exposure * c[2])};
}

RadianceImage read_radiance_image(std::span<const unsigned char> bytes, std::string_view name) {
  const RadianceHeader header = read_radiance_header(bytes, name);
  if (header.width < 1 || header.height < 1 || header.width > 32768 || header.height > 32768)
    fail(name, fmt::format("invalid size {}x{}", header.width, header.height));
  const std::vector<std::uint8_t> texels = read_radiance_texels(bytes, header, name);
  RadianceImage image;
  image.width = static_cast<int>(header.width);
  image.height = static_cast<int>(header.height);
  image.space = radiance_color_space(header, name);
  image.rgb = radiance_texels_as_floats(texels, radiance_texel_factors(header));
  return image;
}

std::vector<float> radiance_texels_as_floats(const std::vector<std::uint8_t>& rgbe, const Vec3d& factors) {
  // One channel: mantissa · 2^(exponent − 136), 0 for exponent 0 (stb_image's conversion,
  // as scene/texture.h's rgbe_value; exact in float).
  const auto value = [](std::uint8_t mantissa, std::uint8_t exponent) {
    return exponent == 0 ? 0.0f : static_cast<float>(std::ldexp(static_cast<double>(mantissa), exponent - 136));
  };
  std::vector<float> rgb(rgbe.size() / 4 * 3);
  for (std::size_t t = 0; t < rgbe.size() / 4; ++t)
    for (std::size_t k = 0; k < 3; ++k)
      rgb[3 * t + k] = static_cast<float>(value(rgbe[4 * t + k], rgbe[4 * t + 3]) * factors[k]);
  return rgb;
}

}  // namespace prism
