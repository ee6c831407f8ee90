#include "prism/io/openexr_header.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/io/read_to_end.h"

namespace prism {
namespace {

std::int32_t read_le32(const unsigned char* p) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
                                   static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24);
}

// Sizes of OpenEXR's fixed-size attribute types (OpenEXR file layout, "Attribute types").
// OpenEXR reads a value of a known type by its type, not by the declared size, and goes on
// from there; a walk that skipped the declared size would lose step with it (the fuzz
// target found a float declaring 247 bytes, after which OpenEXR read a string of the value
// as an attribute claiming 1.7 GB). So a known type must declare its own size.
std::optional<std::int32_t> openexr_fixed_attribute_size(std::string_view type) {
  static constexpr std::pair<std::string_view, std::int32_t> kSizes[] = {
      {"box2i", 16},    {"box2f", 16},          {"chromaticities", 32}, {"compression", 1}, {"double", 8},
      {"envmap", 1},    {"float", 4},           {"int", 4},             {"keycode", 28},    {"lineOrder", 1},
      {"m33f", 36},     {"m33d", 72},           {"m44f", 64},           {"m44d", 128},      {"rational", 8},
      {"tiledesc", 9},  {"timecode", 8},        {"v2i", 8},             {"v2f", 8},         {"v2d", 16},
      {"v3i", 12},      {"v3f", 12},            {"v3d", 24},            {"deepImageState", 1}};
  for (const auto& [name, size] : kSizes)
    if (name == type) return size;
  return std::nullopt;
}


// The same from a "chlist" attribute's value. Entries: a name, then pixel type (1: HALF),
// pLinear and 3 reserved bytes, x and y sampling (OpenEXR file layout, "chlist"); a list
// that does not parse has no colour channels.
void read_openexr_channel_list(const unsigned char* value, std::size_t size, OpenExrFirstPart& part) {
  unsigned rgb = 0, rgb_half = 0;  // bit k: channel "RGB"[k] is listed / is half
  bool y = false, y_half = false;
  std::size_t pos = 0;
  while (pos < size && value[pos] != 0) {
    const auto* entry = reinterpret_cast<const char*>(value + pos);
    const std::size_t n = ::strnlen(entry, size - pos);
    if (pos + n + 1 + 16 > size) return;
    const std::string_view channel(entry, n);
    const unsigned char* fields = value + pos + n + 1;
    const bool half = read_le32(fields) == 1 && read_le32(fields + 8) == 1 && read_le32(fields + 12) == 1;
    const std::size_t k = channel.size() == 1 ? std::string_view("RGB").find(channel[0]) : std::string_view::npos;
    if (k != std::string_view::npos) {
      rgb |= 1u << k;
      rgb_half = half ? rgb_half | 1u << k : rgb_half & ~(1u << k);
    }
    if (channel == "Y") y = true, y_half = half;
    pos += n + 1 + 16;
  }
  if (rgb != 0) {
    part.channels = 3, part.half = rgb_half == 7u;
  } else if (y) {
    part.channels = 1, part.half = y_half;
  }
}

// OpenEXR reads three types by their content, not by the declared size, so a value whose
// content says another size than its declaration puts OpenEXR out of step with the walk (the
// fuzz target found a chlist missing its final null: OpenEXR read on into the next
// attribute, and later allocated a 1.6 GB string the walk never saw), or allocates what the
// content says:
//   chlist       entries (a name of at most `max_name` characters, then 16 bytes) up to an
//                empty name, which must be the value's last byte;
//   stringvector strings, each a 32-bit length and its characters, exactly filling it;
//   preview      width and height, then 4 bytes per pixel, exactly filling it.
// Returns why the value is inconsistent, or nothing.
std::optional<std::string> content_size_mismatch(std::string_view type, const unsigned char* value, std::size_t size,
                                                 std::size_t max_name) {
  if (type == "chlist") {
    std::size_t pos = 0;
    while (pos < size && value[pos] != 0) {
      const std::size_t n = ::strnlen(reinterpret_cast<const char*>(value + pos), size - pos);
      if (n > max_name) return fmt::format("a channel name of {} characters, over {}", n, max_name);
      pos += n + 1 + 16;
    }
    if (pos + 1 != size) return std::string("a channel list that does not end where its size says");
  } else if (type == "stringvector") {
    std::size_t pos = 0;
    while (pos < size) {
      if (size - pos < 4) return std::string("a string vector that does not end where its size says");
      const std::int32_t length = read_le32(value + pos);
      pos += 4;
      if (length < 0 || static_cast<std::size_t>(length) > size - pos)
        return fmt::format("a string of {} bytes in a string vector of {}", length, size);
      pos += static_cast<std::size_t>(length);
    }
  } else if (type == "preview") {
    if (size < 8) return std::string("a preview without its size");
    const auto width = static_cast<std::uint32_t>(read_le32(value)), height = static_cast<std::uint32_t>(read_le32(value + 4));
    if (8 + 4 * static_cast<std::uint64_t>(width) * height != size)
      return fmt::format("a preview of {}x{} pixels in {} bytes", width, height, size);
  }
  return std::nullopt;
}

}  // namespace

void check_image_dimensions(long width, long height, int max_dimension, std::string_view name) {
  if (width <= 0 || height <= 0)
    throw IoError(fmt::format("cannot read image '{}': invalid size {}x{}", name, width, height));
  if (width > max_dimension || height > max_dimension)
    throw IoError(fmt::format("cannot read image '{}': {}x{} pixels exceeds the limit of {}x{}", name, width, height,
                              max_dimension, max_dimension));
}

OpenExrFirstPart check_openexr_header(std::span<const unsigned char> bytes, int max_dimension,
                                      std::string_view name) {
  const auto corrupt = [&](std::string_view why) {
    throw IoError(fmt::format("cannot read image '{}': corrupt or truncated OpenEXR header ({})", name, why));
  };
  if (bytes.size() < 8) corrupt("too short");
  const std::uint32_t version = read_le32(bytes.data() + 4);
  const bool multipart = (version & 0x1000) != 0;
  // OpenEXR reads attribute and type names of at most 31 characters, or 255 with the
  // long-names flag (0x400), and carries on past a longer one's 31st character as if the
  // name had ended there; a walk that read the whole name would then see other attributes
  // than OpenEXR does, and miss a value size it allocates (found by fuzz_image_readers:
  // a 42-character name, then a string attribute of 1.7 GB).
  const std::size_t max_name = (version & 0x400) ? 255 : 31;
  std::size_t pos = 8;
  const auto read_string = [&] {
    const auto* begin = reinterpret_cast<const char*>(bytes.data() + pos);
    const std::size_t n = ::strnlen(begin, std::min<std::size_t>(bytes.size() - pos, 256));
    if (pos + n >= bytes.size() || n > 255) corrupt("unterminated attribute name");
    if (n > max_name)
      corrupt(fmt::format("a name of {} characters, over OpenEXR's {}{}", n, max_name,
                          max_name == 31 ? " without the long-names flag" : ""));
    pos += n + 1;
    return std::string_view(begin, n);
  };
  OpenExrFirstPart first;
  for (int header = 0;; ++header) {
    long width = 0, height = 0, tile_x = 0, tile_y = 0;
    bool any = false;
    OpenExrFirstPart colour;
    for (;;) {
      if (pos >= bytes.size()) corrupt("no end of header");
      const std::string_view attribute = read_string();
      if (attribute.empty()) break;
      any = true;
      const std::string_view type = read_string();
      if (pos + 4 > bytes.size()) corrupt("attribute size missing");
      const std::int32_t size = read_le32(bytes.data() + pos);
      pos += 4;
      if (size < 0 || static_cast<std::size_t>(size) > bytes.size() - pos)
        corrupt(fmt::format("attribute '{}' claims {} bytes", attribute, size));
      if (const auto fixed = openexr_fixed_attribute_size(type); fixed && *fixed != size)
        corrupt(fmt::format("attribute '{}' of type {} claims {} bytes, not {}", attribute, type, size, *fixed));
      const unsigned char* value = bytes.data() + pos;
      if (const auto why = content_size_mismatch(type, value, static_cast<std::size_t>(size), max_name))
        corrupt(fmt::format("attribute '{}' of type {}: {}", attribute, type, *why));
      if (attribute == "dataWindow" && type == "box2i" && size == 16) {
        width = static_cast<long>(read_le32(value + 8)) - read_le32(value) + 1;
        height = static_cast<long>(read_le32(value + 12)) - read_le32(value + 4) + 1;
      }
      if (attribute == "channels" && type == "chlist")
        read_openexr_channel_list(value, static_cast<std::size_t>(size), colour);
      if (attribute == "tiles" && type == "tiledesc" && size >= 8) {
        tile_x = static_cast<std::uint32_t>(read_le32(value));
        tile_y = static_cast<std::uint32_t>(read_le32(value + 4));
      }
      pos += static_cast<std::size_t>(size);
    }
    if (!any) {
      if (header == 0) corrupt("empty header");
      return first;  // the empty header that ends a multi-part file's headers
    }
    check_image_dimensions(width, height, max_dimension, name);
    if (header == 0) first = {width, height, colour.channels, colour.half};
    if (tile_x > 0 && tile_y > 0) {
      const double tiles = std::ceil(static_cast<double>(width) / tile_x) * std::ceil(static_cast<double>(height) / tile_y);
      if (8.0 * tiles > static_cast<double>(bytes.size())) corrupt("more tiles than the file can hold");
    } else if (tile_x != 0 || tile_y != 0) {
      corrupt("zero tile size");
    }
    if (!multipart) return first;
  }
}


OpenExrFirstPart check_openexr_file_header(const std::filesystem::path& path, int max_dimension) {
  const std::string name = path.string();
  constexpr std::size_t kPrefixBytes = 1 << 20;
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) throw IoError(fmt::format("cannot read image '{}': {}", name, ec.message()));
  if (size <= kPrefixBytes) return check_openexr_header(read_file_bytes(path, "image"), max_dimension, name);
  std::vector<unsigned char> prefix(kPrefixBytes);
  {
    std::ifstream in(path, std::ios::binary);
    in.read(reinterpret_cast<char*>(prefix.data()), static_cast<std::streamsize>(prefix.size()));
    if (static_cast<std::size_t>(in.gcount()) != prefix.size())
      throw IoError(fmt::format("cannot read image '{}': the file shrank while it was read", name));
  }
  try {
    return check_openexr_header(prefix, max_dimension, name);
  } catch (const IoError&) {
    // A header longer than the prefix (a large preview or metadata) reads as cut short
    // there: the whole file decides.
    return check_openexr_header(read_file_bytes(path, "image"), max_dimension, name);
  }
}

}  // namespace prism
