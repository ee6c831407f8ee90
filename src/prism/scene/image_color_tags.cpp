#include "prism/scene/image_color_tags.h"

#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <vector>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/icc_profile.h"
#include "prism/color/transfer_functions.h"
#include "prism/core/error.h"

namespace prism {
namespace {

std::uint32_t be32(const unsigned char* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | p[3];
}

// The sRGB EOTF (IEC 61966-2-1 §5.2) as ICC.1's parametric function 3.
color::IccCurve srgb_curve() {
  color::IccCurve c;
  c.kind = color::IccCurve::Kind::parametric;
  c.function = 3;
  c.params = {2.4, 1.0 / 1.055, 0.055 / 1.055, 1.0 / 12.92, 0.04045, 0.0, 0.0};
  return c;
}
color::IccCurve power_curve(double gamma) {
  color::IccCurve c;
  c.kind = color::IccCurve::Kind::gamma;
  c.gamma = gamma;
  return c;
}
void set_curves(ImageColorTags& tags, const color::IccCurve& c) { tags.curves = {c, c, c}; }

ImageColorTags srgb_tags() {
  ImageColorTags t;
  set_curves(t, srgb_curve());
  return t;
}

void pass_over(ImageColorTags& tags, const std::string& what) {
  tags.passed_over += (tags.passed_over.empty() ? "" : "; ") + what;
}

// Whether decoding 8-bit codes with `profile` gives what the sRGB table gives: every code's
// value re-encoded with sRGB within half a code (rounding in the profile's own tables and
// s15Fixed16 numbers), and colorants within 2e-3 of sRGB's adapted to D50 (profiles in
// circulation differ from the Bradford-adapted matrix in the fourth decimal).
bool matches_srgb(const color::IccMatrixTrc& profile) {
  for (int channel = 0; channel < (profile.gray ? 1 : 3); ++channel)
    for (int code = 0; code <= 255; ++code) {
      const double v = profile.curves[static_cast<std::size_t>(channel)](code / 255.0);
      if (std::abs(color::srgb_encode(v) * 255.0 - code) > 0.5) return false;
    }
  if (profile.gray) return true;
  const Mat3 srgb = color::icc_colorant_matrix(color::color_space("srgb"));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (std::abs(profile.colorants.m[i][j] - srgb.m[i][j]) > 2e-3) return false;
  return true;
}

// Uses an ICC profile where it reads; says why not otherwise. True when used.
bool use_icc_profile(ImageColorTags& tags, std::span<const std::uint8_t> bytes, const std::string& label) {
  try {
    const color::IccMatrixTrc profile = color::read_icc_matrix_trc(bytes);
    const std::string source =
        profile.description.empty() ? label : fmt::format("{} '{}'", label, profile.description);
    if (matches_srgb(profile)) {
      tags.srgb = true;
      tags.source = source;
      return true;
    }
    tags.srgb = false;
    tags.source = source;
    tags.curves = profile.gray ? std::array{profile.curves[0], profile.curves[0], profile.curves[0]} : profile.curves;
    if (!profile.gray) tags.pcs_colorants = profile.colorants;
    return true;
  } catch (const Error& e) {
    pass_over(tags, fmt::format("{} not read ({})", label, e.what()));
    return false;
  }
}

// zlib data (RFC 1950) inflated, or nothing with the reason: ICC profiles are kilobytes
// (lookup-table ones a few megabytes), so more than 64 MiB is refused, not allocated.
std::optional<std::vector<std::uint8_t>> inflate_profile(std::span<const unsigned char> in, std::string& why) {
  constexpr std::size_t kMaxBytes = std::size_t{64} << 20;
  z_stream z{};
  if (inflateInit(&z) != Z_OK) {
    why = "zlib failed to start";
    return std::nullopt;
  }
  std::vector<std::uint8_t> out;
  z.next_in = const_cast<Bytef*>(in.data());
  z.avail_in = static_cast<uInt>(in.size());
  int status = Z_OK;
  while (status == Z_OK) {
    if (out.size() >= kMaxBytes) {
      inflateEnd(&z);
      why = "it inflates to more than 64 MiB";
      return std::nullopt;
    }
    const std::size_t done = out.size();
    out.resize(std::min(kMaxBytes, std::max<std::size_t>(4096, done * 2)));
    z.next_out = out.data() + done;
    z.avail_out = static_cast<uInt>(out.size() - done);
    status = inflate(&z, Z_NO_FLUSH);
    out.resize(out.size() - z.avail_out);
    if (status == Z_BUF_ERROR && z.avail_in == 0) break;  // the stream ends early
    if (status == Z_BUF_ERROR) status = Z_OK;            // room was short: grow and go on
  }
  inflateEnd(&z);
  if (status != Z_STREAM_END) {
    why = "its compressed profile is corrupt or cut short";
    return std::nullopt;
  }
  return out;
}

struct PngChunks {
  std::optional<std::span<const unsigned char>> cicp, iccp, srgb, gama, chrm;
};

// The colour chunks before the first IDAT (PNG §5.6: they must precede it); the first of
// each kind. Chunk lengths were checked against the file before (texture_file.cpp).
PngChunks png_chunks(std::span<const unsigned char> png) {
  PngChunks c;
  for (std::size_t pos = 8; pos + 8 <= png.size();) {
    const std::size_t length = be32(png.data() + pos);
    if (length > png.size() - pos - 8) break;
    const std::span<const unsigned char> data = png.subspan(pos + 8, length);
    const auto is = [&](const char* type) { return std::memcmp(png.data() + pos + 4, type, 4) == 0; };
    if (is("IDAT") || is("IEND")) break;
    if (is("cICP") && !c.cicp) c.cicp = data;
    if (is("iCCP") && !c.iccp) c.iccp = data;
    if (is("sRGB") && !c.srgb) c.srgb = data;
    if (is("gAMA") && !c.gama) c.gama = data;
    if (is("cHRM") && !c.chrm) c.chrm = data;
    pos += 12 + length;
  }
  return c;
}

// cICP (PNG §11.3.2.6; ITU-T H.273 Tables 2 and 3). True when used.
bool use_cicp(ImageColorTags& tags, std::span<const unsigned char> d, std::string_view name) {
  if (d.size() != 4) {
    pass_over(tags, fmt::format("cICP chunk of {} bytes (4 expected) ignored", d.size()));
    return false;
  }
  const unsigned primaries = d[0], transfer = d[1], matrix = d[2], full_range = d[3];
  const std::string label = fmt::format("cICP {}/{}/{}/{}", primaries, transfer, matrix, full_range);
  if (matrix != 0 || full_range > 1) {
    pass_over(tags, label + " ignored (PNG images are RGB: matrix coefficients 0, range flag 0 or 1)");
    return false;
  }
  if (transfer == 16 || transfer == 18)
    throw IoError(fmt::format("cannot read image '{}': its {} says {} HDR signals, which a texture does not take "
                              "(save it as OpenEXR)",
                              name, label, transfer == 16 ? "PQ (SMPTE ST 2084)" : "HLG (ARIB STD-B67)"));
  std::optional<color::IccCurve> curve;
  switch (transfer) {
    case 1: case 6: case 14: case 15: curve = power_curve(2.4); break;  // the BT.709 family, shown through BT.1886
    case 4: curve = power_curve(2.2); break;                           // BT.470 System M
    case 5: curve = power_curve(2.8); break;                           // BT.470 System B, G
    case 8: curve = color::IccCurve{}; break;                          // linear
    case 13: curve = srgb_curve(); break;                              // IEC 61966-2-1
    default: break;
  }
  std::optional<color::Primaries> p;
  const auto primaries_of = [](const char* space) {
    const color::ColorSpace& s = color::color_space(space);
    return color::Primaries{s.red, s.green, s.blue, s.white};
  };
  switch (primaries) {
    case 1: p = primaries_of("srgb"); break;
    case 9: p = primaries_of("rec2020"); break;
    case 11: p = primaries_of("dci-p3"); break;
    case 12: p = primaries_of("display-p3"); break;
    default: break;
  }
  if (!curve || !p) {
    pass_over(tags, label + fmt::format(" ignored (H.273 {} {} is not one Prism reads)", !p ? "colour primaries" : "transfer characteristics",
                                        !p ? primaries : transfer));
    return false;
  }
  tags.source = label;
  tags.narrow_range = full_range == 0;
  tags.srgb = primaries == 1 && transfer == 13 && full_range == 1;
  set_curves(tags, *curve);
  if (primaries != 1) tags.primaries = p;
  return true;
}

}  // namespace

bool image_file_has_color_tags(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char head[12];
  if (!in.read(reinterpret_cast<char*>(head), 8)) return false;
  if (std::memcmp(head, "\x89PNG\r\n\x1a\n", 8) == 0) {
    // cICP and iCCP always count; cHRM and gAMA only without an sRGB chunk, which
    // overrides them (read_png_color_tags).
    bool srgb = false, chromaticities_or_gamma = false;
    const auto is = [&](const char* tag) { return std::memcmp(head + 4, tag, 4) == 0; };
    while (in.read(reinterpret_cast<char*>(head), 8)) {
      if (is("cICP") || is("iCCP")) return true;
      srgb = srgb || is("sRGB");
      chromaticities_or_gamma = chromaticities_or_gamma || is("cHRM") || is("gAMA");
      if (is("IDAT") || is("IEND")) break;
      in.seekg(static_cast<std::streamoff>(be32(head)) + 4, std::ios::cur);
    }
    return chromaticities_or_gamma && !srgb;
  }
  if (head[0] != 0xff || head[1] != 0xd8) return false;
  in.seekg(2);
  while (in.read(reinterpret_cast<char*>(head), 4)) {
    if (head[0] != 0xff || head[1] == 0xda || head[1] == 0xd9) return false;
    const std::streamoff length = (head[2] << 8) | head[3];
    if (head[1] == 0xe2 && length >= 14) {
      char id[12];
      if (!in.read(id, 12)) return false;
      if (std::memcmp(id, "ICC_PROFILE\0", 12) == 0) return true;
      in.seekg(length - 14, std::ios::cur);
    } else {
      in.seekg(length - 2, std::ios::cur);
    }
  }
  return false;
}

ImageColorTags read_png_color_tags(std::span<const unsigned char> png, std::string_view name) {
  ImageColorTags tags = srgb_tags();
  const PngChunks c = png_chunks(png);
  if (c.cicp && use_cicp(tags, *c.cicp, name)) return tags;
  if (c.iccp) {
    // iCCP (§11.3.2.4): a profile name of 1 to 79 bytes, a zero, method 0 (zlib), the data.
    const auto d = *c.iccp;
    const auto zero = std::find(d.begin(), d.begin() + std::min<std::size_t>(d.size(), 80), 0);
    const std::size_t name_length = static_cast<std::size_t>(zero - d.begin());
    if (zero == d.end() || name_length == 0 || name_length >= 80 || name_length + 2 > d.size() || d[name_length + 1] != 0) {
      pass_over(tags, "iCCP chunk malformed (no profile name or an unknown compression method) ignored");
    } else {
      std::string why;
      if (const auto profile = inflate_profile(d.subspan(name_length + 2), why)) {
        if (use_icc_profile(tags, *profile, "ICC profile")) return tags;
      } else {
        pass_over(tags, "iCCP chunk ignored (" + why + ")");
      }
    }
  }
  if (c.srgb) {
    tags.source = "sRGB chunk";  // nothing before it was used: the tags still say sRGB
    return tags;
  }
  // gAMA (§11.3.2.3) is the encoding exponent × 100000; 45455, what an sRGB encoder writes
  // beside its sRGB chunk (§12.2), is read as sRGB, as browsers do.
  std::optional<double> decoding_gamma;
  bool gamma_is_srgb = false;
  if (c.gama) {
    const std::uint32_t g = c.gama->size() == 4 ? be32(c.gama->data()) : 0;
    if (g == 0) pass_over(tags, "gAMA chunk of 0 or of the wrong size ignored");
    else if (std::abs(static_cast<double>(g) - 45455.0) <= 5.0) gamma_is_srgb = true;
    else decoding_gamma = 100000.0 / g;
  }
  std::optional<color::Primaries> chromaticities;
  if (c.chrm) {
    // cHRM (§11.3.2.2): white, red, green, blue x and y, each × 100000.
    if (c.chrm->size() != 32) {
      pass_over(tags, "cHRM chunk of the wrong size ignored");
    } else {
      std::array<double, 8> v;
      for (std::size_t i = 0; i < 8; ++i) v[i] = be32(c.chrm->data() + 4 * i) / 100000.0;
      const color::Primaries p{{v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}, {v[0], v[1]}};
      try {
        color::validate_primaries(p);
        const color::ColorSpace& srgb = color::color_space("srgb");
        const color::Primaries srgb_p{srgb.red, srgb.green, srgb.blue, srgb.white};
        // Within the chunk's own rounding (1e-5) of sRGB's, and 1e-3 for writers that round
        // to three decimals: sRGB's.
        bool same = true;
        const color::Chromaticity a[4] = {p.red, p.green, p.blue, p.white}, b[4] = {srgb_p.red, srgb_p.green, srgb_p.blue, srgb_p.white};
        for (int i = 0; i < 4; ++i) same = same && std::abs(a[i].x - b[i].x) <= 1e-3 && std::abs(a[i].y - b[i].y) <= 1e-3;
        if (!same) chromaticities = p;
      } catch (const Error& e) {
        pass_over(tags, fmt::format("cHRM chunk ignored ({})", e.what()));
      }
    }
  }
  if (!decoding_gamma && !chromaticities) {
    if (gamma_is_srgb || c.chrm) tags.source = "gAMA/cHRM of sRGB";
    return tags;
  }
  tags.srgb = false;
  if (decoding_gamma) set_curves(tags, power_curve(*decoding_gamma));
  tags.primaries = chromaticities;
  tags.source = decoding_gamma && chromaticities ? fmt::format("gAMA 1/{:.3g} and cHRM", *decoding_gamma)
                : decoding_gamma                  ? fmt::format("gAMA 1/{:.3g}", *decoding_gamma)
                                                  : std::string("cHRM");
  return tags;
}

ImageColorTags read_jpeg_color_tags(std::span<const unsigned char> jpeg, std::string_view /*name*/) {
  ImageColorTags tags = srgb_tags();
  // ICC.1 Annex B.4: APP2 segments "ICC_PROFILE\0", a 1-based sequence number and the
  // count, then that part of the profile; the parts in sequence order are the profile.
  std::map<int, std::span<const unsigned char>> parts;
  int count = 0;
  bool consistent = true;
  for (std::size_t pos = 2; pos + 4 <= jpeg.size();) {
    if (jpeg[pos] != 0xff) break;
    const unsigned marker = jpeg[pos + 1];
    if (marker == 0xff) { ++pos; continue; }  // fill byte
    if (marker == 0xda || marker == 0xd9) break;  // start of scan, end of image
    const std::size_t length = (std::size_t{jpeg[pos + 2]} << 8) | jpeg[pos + 3];
    if (length < 2 || pos + 2 + length > jpeg.size()) break;
    const auto segment = jpeg.subspan(pos + 4, length - 2);
    if (marker == 0xe2 && segment.size() >= 14 && std::memcmp(segment.data(), "ICC_PROFILE\0", 12) == 0) {
      const int sequence = segment[12], total = segment[13];
      if (count != 0 && total != count) consistent = false;
      count = total;
      if (sequence < 1 || sequence > total || !parts.emplace(sequence, segment.subspan(14)).second) consistent = false;
    }
    pos += 2 + length;
  }
  if (parts.empty()) return tags;
  if (!consistent || static_cast<int>(parts.size()) != count) {
    pass_over(tags, "ICC profile ignored (its APP2 parts are missing or numbered inconsistently)");
    return tags;
  }
  std::vector<std::uint8_t> profile;
  for (const auto& [sequence, part] : parts) profile.insert(profile.end(), part.begin(), part.end());
  use_icc_profile(tags, profile, "ICC profile");
  return tags;
}

Mat3 image_color_conversion(const ImageColorTags& tags, const color::ColorSpace& target) {
  if (tags.pcs_colorants) return inverse(color::icc_colorant_matrix(target)) * *tags.pcs_colorants;
  if (tags.primaries) return color::conversion_matrix(color::make_color_space("image", *tags.primaries), target);
  return color::conversion_matrix(color::color_space("srgb"), target);
}

double decode_tagged_code(const ImageColorTags& tags, int channel, unsigned code, unsigned max_code) {
  double x = static_cast<double>(code) / max_code;
  if (tags.narrow_range) {
    // H.273 Equation 20ff.: black at 16 and white at 235, scaled to the bit depth.
    const double scale = (max_code + 1.0) / 256.0;
    x = (code - 16.0 * scale) / (219.0 * scale);
  }
  return tags.curves[static_cast<std::size_t>(channel)](x);
}

}  // namespace prism
