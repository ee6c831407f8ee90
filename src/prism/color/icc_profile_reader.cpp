#include "prism/color/icc_profile_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <string_view>

#include "prism/core/error.h"

namespace prism::color {
namespace {

// ICC.1 §4: every number is big-endian.
std::uint32_t be32(const std::uint8_t* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | p[3];
}
std::uint16_t be16(const std::uint8_t* p) { return static_cast<std::uint16_t>((p[0] << 8) | p[1]); }
// s15Fixed16Number (§4.6).
double s15_fixed16(const std::uint8_t* p) { return static_cast<std::int32_t>(be32(p)) / 65536.0; }

bool signature_is(const std::uint8_t* p, std::string_view s) { return std::memcmp(p, s.data(), 4) == 0; }

[[noreturn]] void refuse(const std::string& why) { throw Error(why); }

class Profile {
 public:
  explicit Profile(std::span<const std::uint8_t> bytes) : bytes_(bytes) {
    // §7.2: a 128-byte header, then the tag count and 12-byte tag entries.
    if (bytes.size() < 132 || !signature_is(bytes.data() + 36, "acsp")) refuse("not an ICC profile");
    const std::uint32_t declared = be32(bytes.data());
    if (declared > bytes.size()) refuse(fmt::format("it declares {} bytes but holds {}", declared, bytes.size()));
    if (declared < 132) refuse("not an ICC profile (it declares fewer bytes than a header)");
    bytes_ = bytes.first(declared);
    const std::uint32_t count = be32(bytes_.data() + 128);
    if (count > (bytes_.size() - 132) / 12) refuse(fmt::format("its tag table claims {} tags, more than it holds", count));
    tags_ = bytes_.subspan(132, std::size_t{count} * 12);
  }
  std::string_view color_space() const { return {reinterpret_cast<const char*>(bytes_.data() + 16), 4}; }
  std::string_view connection_space() const { return {reinterpret_cast<const char*>(bytes_.data() + 20), 4}; }

  // The data of tag `signature`, or nothing without it. Throws where it runs past the end.
  std::optional<std::span<const std::uint8_t>> tag(std::string_view signature) const {
    for (std::size_t i = 0; i + 12 <= tags_.size(); i += 12) {
      if (!signature_is(tags_.data() + i, signature)) continue;
      const std::uint64_t offset = be32(tags_.data() + i + 4), size = be32(tags_.data() + i + 8);
      if (offset + size > bytes_.size() || size < 8)
        refuse(fmt::format("its {} tag runs past the profile's end", signature));
      return bytes_.subspan(offset, size);
    }
    return std::nullopt;
  }
  std::span<const std::uint8_t> required(std::string_view signature) const {
    const auto t = tag(signature);
    if (!t) refuse(fmt::format("no {} tag (a profile of lookup tables only?)", signature));
    return *t;
  }

 private:
  std::span<const std::uint8_t> bytes_, tags_;
};

// XYZType (§10.31): one XYZNumber after the type signature and 4 reserved bytes.
Vec3d read_xyz(std::span<const std::uint8_t> t, std::string_view signature) {
  if (!signature_is(t.data(), "XYZ ") || t.size() < 20) refuse(fmt::format("its {} tag is not an XYZType", signature));
  return {s15_fixed16(t.data() + 8), s15_fixed16(t.data() + 12), s15_fixed16(t.data() + 16)};
}

IccCurve read_curve(std::span<const std::uint8_t> t, std::string_view signature) {
  IccCurve c;
  if (signature_is(t.data(), "curv")) {
    if (t.size() < 12) refuse(fmt::format("its {} tag is cut short", signature));
    const std::uint32_t n = be32(t.data() + 8);
    if (n > (t.size() - 12) / 2) refuse(fmt::format("its {} tag claims {} entries, more than it holds", signature, n));
    if (n == 0) return c;  // identity
    if (n == 1) {
      c.kind = IccCurve::Kind::gamma;
      c.gamma = be16(t.data() + 12) / 256.0;  // u8Fixed8Number
      if (!(c.gamma > 0.0)) refuse(fmt::format("its {} tag has a gamma of 0", signature));
      return c;
    }
    c.kind = IccCurve::Kind::table;
    c.table.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) c.table[i] = be16(t.data() + 12 + 2 * i) / 65535.0;
    return c;
  }
  if (signature_is(t.data(), "para")) {
    if (t.size() < 12) refuse(fmt::format("its {} tag is cut short", signature));
    c.kind = IccCurve::Kind::parametric;
    c.function = be16(t.data() + 8);
    static constexpr std::size_t kParams[5] = {1, 3, 4, 5, 7};  // §10.18 Table 68
    if (c.function > 4) refuse(fmt::format("its {} tag has parametric function {}, which ICC.1 does not define", signature, c.function));
    const std::size_t n = kParams[c.function];
    if (t.size() < 12 + 4 * n) refuse(fmt::format("its {} tag is cut short", signature));
    for (std::size_t i = 0; i < n; ++i) c.params[i] = s15_fixed16(t.data() + 12 + 4 * i);
    return c;
  }
  refuse(fmt::format("its {} tag is neither a curveType nor a parametricCurveType", signature));
}

// 'desc': textDescriptionType (v2: an ASCII count and string) or multiLocalizedUnicodeType
// (v4, §10.15: UTF-16BE records; the first record's characters below 128 are kept).
std::string read_description(std::span<const std::uint8_t> t) {
  std::string text;
  if (signature_is(t.data(), "desc") && t.size() >= 12) {
    const std::uint32_t n = std::min<std::uint64_t>(be32(t.data() + 8), t.size() - 12);
    for (std::uint32_t i = 0; i < n && t[12 + i] != 0; ++i) text += static_cast<char>(t[12 + i]);
  } else if (signature_is(t.data(), "mluc") && t.size() >= 28) {
    const std::uint64_t length = be32(t.data() + 20), offset = be32(t.data() + 24);
    if (offset + length <= t.size())
      for (std::uint64_t i = 0; i + 1 < length; i += 2) {
        const std::uint16_t u = be16(t.data() + offset + i);
        text += u > 0 && u < 128 ? static_cast<char>(u) : '?';
      }
  }
  std::erase_if(text, [](char ch) { return static_cast<unsigned char>(ch) < 32; });
  return text;
}

}  // namespace

double IccCurve::operator()(double x) const {
  x = std::clamp(x, 0.0, 1.0);
  switch (kind) {
    case Kind::identity: return x;
    case Kind::gamma: return std::pow(x, gamma);
    case Kind::table: {
      const double position = x * static_cast<double>(table.size() - 1);
      const auto i = std::min(static_cast<std::size_t>(position), table.size() - 2);
      const double f = position - static_cast<double>(i);
      return table[i] + f * (table[i + 1] - table[i]);
    }
    case Kind::parametric: {
      // Plain names, not a structured binding: the lambda captures g (clang 14 cannot
      // capture bindings).
      const double g = params[0], a = params[1], b = params[2], c = params[3], d = params[4], e = params[5],
                   f = params[6];
      const auto power = [g](double base) { return base > 0.0 ? std::pow(base, g) : 0.0; };
      switch (function) {
        case 0: return std::pow(x, g);
        case 1: return a != 0.0 && x >= -b / a ? power(a * x + b) : 0.0;
        case 2: return a != 0.0 && x >= -b / a ? power(a * x + b) + c : c;
        case 3: return x >= d ? power(a * x + b) : c * x;
        default: return x >= d ? power(a * x + b) + e : c * x + f;
      }
    }
  }
  return x;
}

IccMatrixTrc read_icc_matrix_trc(std::span<const std::uint8_t> bytes) {
  const Profile profile(bytes);
  IccMatrixTrc result;
  const std::string_view space = profile.color_space();
  if (space != "RGB " && space != "GRAY")
    refuse(fmt::format("a profile of '{}' data, not RGB or grey", std::string(space)));
  if (profile.connection_space() != "XYZ ")
    refuse("its connection space is CIELAB, which a matrix/TRC profile cannot have");
  if (const auto desc = profile.tag("desc")) result.description = read_description(*desc);
  if (space == "GRAY") {
    result.gray = true;
    result.curves[0] = read_curve(profile.required("kTRC"), "kTRC");
    return result;
  }
  result.colorants = Mat3::from_columns(read_xyz(profile.required("rXYZ"), "rXYZ"),
                                        read_xyz(profile.required("gXYZ"), "gXYZ"),
                                        read_xyz(profile.required("bXYZ"), "bXYZ"));
  result.curves = {read_curve(profile.required("rTRC"), "rTRC"), read_curve(profile.required("gTRC"), "gTRC"),
                   read_curve(profile.required("bTRC"), "bTRC")};
  if (!(std::abs(determinant(result.colorants)) > 1e-9)) refuse("its colorants are not independent");
  return result;
}

}  // namespace prism::color
