#include "prism/scene/loaders/ply_mesh.h"

#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/io/read_to_end.h"

namespace prism::loaders {
namespace {

enum class PlyFormat { ascii, binary_le, binary_be };
enum class PlyType { i8, u8, i16, u16, i32, u32, f32, f64 };

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::f32;
  bool is_list = false;
  PlyType count_type = PlyType::u8;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

std::optional<PlyType> parse_type(std::string_view t) {
  if (t == "char" || t == "int8") return PlyType::i8;
  if (t == "uchar" || t == "uint8") return PlyType::u8;
  if (t == "short" || t == "int16") return PlyType::i16;
  if (t == "ushort" || t == "uint16") return PlyType::u16;
  if (t == "int" || t == "int32") return PlyType::i32;
  if (t == "uint" || t == "uint32") return PlyType::u32;
  if (t == "float" || t == "float32") return PlyType::f32;
  if (t == "double" || t == "float64") return PlyType::f64;
  return std::nullopt;
}

std::size_t type_size(PlyType t) {
  switch (t) {
    case PlyType::i8: case PlyType::u8: return 1;
    case PlyType::i16: case PlyType::u16: return 2;
    case PlyType::i32: case PlyType::u32: case PlyType::f32: return 4;
    case PlyType::f64: return 8;
  }
  return 1;
}

// Reads values one at a time from the body, in any of the three encodings.
class PlyBody {
 public:
  PlyBody(std::span<const unsigned char> bytes, std::size_t offset, PlyFormat format, std::string_view source)
      : bytes_(bytes), pos_(offset), format_(format), source_(source) {}

  std::size_t remaining() const { return bytes_.size() - pos_; }

  double read(PlyType type) {
    if (format_ == PlyFormat::ascii) return read_ascii(type);
    const std::size_t n = type_size(type);
    if (remaining() < n) fail("the file ends inside the data");
    unsigned char b[8];
    std::memcpy(b, bytes_.data() + pos_, n);
    pos_ += n;
    if ((format_ == PlyFormat::binary_be) != (std::endian::native == std::endian::big))
      for (std::size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
    switch (type) {
      case PlyType::i8: return static_cast<double>(static_cast<std::int8_t>(b[0]));
      case PlyType::u8: return b[0];
      case PlyType::i16: { std::int16_t v; std::memcpy(&v, b, 2); return v; }
      case PlyType::u16: { std::uint16_t v; std::memcpy(&v, b, 2); return v; }
      case PlyType::i32: { std::int32_t v; std::memcpy(&v, b, 4); return v; }
      case PlyType::u32: { std::uint32_t v; std::memcpy(&v, b, 4); return v; }
      case PlyType::f32: { float v; std::memcpy(&v, b, 4); return v; }
      case PlyType::f64: { double v; std::memcpy(&v, b, 8); return v; }
    }
    return 0.0;
  }

  [[noreturn]] void fail(std::string_view what) const {
    throw SceneError(fmt::format("{}: {} (byte {})", source_, what, pos_));
  }

 private:
  double read_ascii(PlyType type) {
    while (pos_ < bytes_.size() && std::isspace(bytes_[pos_])) ++pos_;
    const std::size_t start = pos_;
    while (pos_ < bytes_.size() && !std::isspace(bytes_[pos_])) ++pos_;
    if (start == pos_) fail("the file ends inside the data");
    const char* first = reinterpret_cast<const char*>(bytes_.data()) + start;
    const char* last = reinterpret_cast<const char*>(bytes_.data()) + pos_;
    double v = 0.0;
    const auto [ptr, ec] = std::from_chars(first, last, v);
    if (ec != std::errc() || ptr != last) fail(fmt::format("'{}' is not a number", std::string_view(first, last - first)));
    if (type != PlyType::f32 && type != PlyType::f64 && v != std::floor(v)) fail("expected an integer");
    return v;
  }

  std::span<const unsigned char> bytes_;
  std::size_t pos_;
  PlyFormat format_;
  std::string_view source_;
};

}  // namespace

PlyMesh parse_ply_mesh(std::span<const unsigned char> bytes, std::string_view source) {
  // Header: text lines up to "end_header".
  std::size_t pos = 0;
  int line_number = 0;
  const auto header_fail = [&](std::string_view what) -> void {
    throw SceneError(fmt::format("{}:{}: {}", source, line_number, what));
  };
  const auto next_line = [&]() -> std::optional<std::string> {
    if (pos >= bytes.size()) return std::nullopt;
    std::size_t end = pos;
    while (end < bytes.size() && bytes[end] != '\n') ++end;
    std::string line(reinterpret_cast<const char*>(bytes.data()) + pos, end - pos);
    pos = end < bytes.size() ? end + 1 : end;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return line;
  };
  auto first = next_line();
  if (!first || *first != "ply") {
    line_number = 1;
    header_fail("not a PLY file (the first line is not 'ply')");
  }
  std::optional<PlyFormat> format;
  std::vector<PlyElement> elements;
  bool ended = false;
  while (auto line = next_line()) {
    if (line_number > 10000) header_fail("the header is too long");
    std::istringstream words(*line);
    std::string keyword;
    words >> keyword;
    if (keyword == "end_header") {
      ended = true;
      break;
    }
    if (keyword.empty() || keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "format") {
      std::string f, version;
      words >> f >> version;
      if (f == "ascii") format = PlyFormat::ascii;
      else if (f == "binary_little_endian") format = PlyFormat::binary_le;
      else if (f == "binary_big_endian") format = PlyFormat::binary_be;
      else header_fail(fmt::format("unknown format '{}'", f));
    } else if (keyword == "element") {
      PlyElement e;
      std::string count;
      words >> e.name >> count;
      const auto [ptr, ec] = std::from_chars(count.data(), count.data() + count.size(), e.count);
      if (e.name.empty() || ec != std::errc() || ptr != count.data() + count.size()) header_fail("malformed element line");
      elements.push_back(std::move(e));
    } else if (keyword == "property") {
      if (elements.empty()) header_fail("a property before any element");
      PlyProperty p;
      std::string t;
      words >> t;
      if (t == "list") {
        std::string ct, it;
        words >> ct >> it >> p.name;
        const auto c = parse_type(ct), i = parse_type(it);
        if (!c || !i || p.name.empty()) header_fail("malformed list property");
        p.is_list = true;
        p.count_type = *c;
        p.type = *i;
      } else {
        const auto type = parse_type(t);
        words >> p.name;
        if (!type || p.name.empty()) header_fail(fmt::format("malformed property (type '{}')", t));
        p.type = *type;
      }
      elements.back().properties.push_back(std::move(p));
    } else {
      header_fail(fmt::format("unknown header keyword '{}'", keyword));
    }
  }
  if (!ended) header_fail("the header has no end_header");
  if (!format) header_fail("the header has no format line");

  PlyMesh mesh;
  PlyBody body(bytes, pos, *format, source);
  bool have_vertices = false;
  for (const PlyElement& e : elements) {
    // Each element needs at least one byte (ASCII: two characters) per property, so a
    // count larger than that is a lie we refuse before allocating anything.
    if (e.properties.empty()) continue;  // nothing to read, however many entries it claims
    const std::size_t min_bytes = std::max<std::size_t>(e.properties.size(), 1) * (*format == PlyFormat::ascii ? 2 : 1);
    if (e.count > body.remaining() / min_bytes)
      body.fail(fmt::format("element '{}' claims {} entries, more than the file holds", e.name, e.count));
    const bool is_vertex = e.name == "vertex";
    const bool is_face = e.name == "face";
    int ix = -1, iy = -1, iz = -1, inx = -1, iny = -1, inz = -1, iu = -1, iv = -1, ilist = -1;
    for (int k = 0; k < static_cast<int>(e.properties.size()); ++k) {
      const auto& n = e.properties[k].name;
      if (e.properties[k].is_list) {
        if (is_face && (n == "vertex_indices" || n == "vertex_index")) ilist = k;
        continue;
      }
      if (n == "x") ix = k; else if (n == "y") iy = k; else if (n == "z") iz = k;
      else if (n == "nx") inx = k; else if (n == "ny") iny = k; else if (n == "nz") inz = k;
      else if (n == "u" || n == "s" || n == "texture_u" || n == "texture_s") iu = k;
      else if (n == "v" || n == "t" || n == "texture_v" || n == "texture_t") iv = k;
    }
    if (is_vertex) {
      if (have_vertices) body.fail("more than one vertex element");
      if (ix < 0 || iy < 0 || iz < 0) body.fail("the vertex element lacks x, y or z");
      have_vertices = true;
      const bool normals = inx >= 0 && iny >= 0 && inz >= 0, uvs = iu >= 0 && iv >= 0;
      mesh.positions.reserve(e.count);
      if (normals) mesh.normals.reserve(e.count);
      if (uvs) mesh.uvs.reserve(e.count);
    }
    if (is_face && ilist < 0) body.fail("the face element has no vertex_indices list");
    std::vector<double> values(e.properties.size());
    std::vector<std::uint32_t> polygon;
    for (std::uint64_t i = 0; i < e.count; ++i) {
      for (std::size_t k = 0; k < e.properties.size(); ++k) {
        const PlyProperty& p = e.properties[k];
        if (!p.is_list) {
          values[k] = body.read(p.type);
          continue;
        }
        // Written so that NaN (a float-typed count or index) fails the check: converting
        // it to an integer would be undefined behaviour.
        const double count = body.read(p.count_type);
        if (!(count >= 0 && count <= static_cast<double>(body.remaining()))) body.fail("a list length is out of range");
        const bool keep = static_cast<int>(k) == ilist;
        polygon.clear();
        for (int c = 0; c < static_cast<int>(count); ++c) {
          const double index = body.read(p.type);
          if (!keep) continue;
          if (!(index >= 0 && index < static_cast<double>(mesh.positions.size())))
            body.fail(fmt::format("face {}: vertex index {} is out of range ({} vertices)", i, index, mesh.positions.size()));
          polygon.push_back(static_cast<std::uint32_t>(index));
        }
        if (keep) {
          if (polygon.size() < 3) body.fail(fmt::format("face {} has fewer than three vertices", i));
          for (std::size_t t = 1; t + 1 < polygon.size(); ++t)
            mesh.indices.insert(mesh.indices.end(), {polygon[0], polygon[t], polygon[t + 1]});
        }
      }
      if (is_vertex) {
        // A finite double beyond float's range would make the conversion undefined; NaN and
        // infinities convert and are reported by the scene's mesh checks with their position.
        const auto f = [&](int k) {
          const double v = values[k];
          if (std::isfinite(v) && std::abs(v) > static_cast<double>(std::numeric_limits<float>::max()))
            body.fail(fmt::format("vertex {}: {} is beyond the range of a float", i, v));
          return static_cast<float>(v);
        };
        mesh.positions.emplace_back(f(ix), f(iy), f(iz));
        if (inx >= 0 && iny >= 0 && inz >= 0) mesh.normals.emplace_back(f(inx), f(iny), f(inz));
        if (iu >= 0 && iv >= 0) mesh.uvs.emplace_back(f(iu), f(iv));
      }
    }
    if (is_face && !have_vertices) body.fail("the face element comes before the vertex element");
  }
  if (!have_vertices) throw SceneError(fmt::format("{}: no vertex element", source));
  return mesh;
}

PlyMesh read_ply_mesh(const std::filesystem::path& path) {
  return parse_ply_mesh(read_file_bytes(path, "PLY mesh"), path.filename().string());
}

}  // namespace prism::loaders
