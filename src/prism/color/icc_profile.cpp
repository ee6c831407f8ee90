#include "prism/color/icc_profile.h"

#include <cmath>

#include "prism/color/chromatic_adaptation.h"

namespace prism::color {
namespace {

// Big-endian writer for the ICC file layout (ICC.1:2022 §4: all numbers big-endian).
class IccWriter {
 public:
  void u8(std::uint8_t v) { bytes.push_back(v); }
  void u16(std::uint16_t v) { u8(static_cast<std::uint8_t>(v >> 8)), u8(static_cast<std::uint8_t>(v)); }
  void u32(std::uint32_t v) { u16(static_cast<std::uint16_t>(v >> 16)), u16(static_cast<std::uint16_t>(v)); }
  void signature(const char (&s)[5]) {
    for (int i = 0; i < 4; ++i) u8(static_cast<std::uint8_t>(s[i]));
  }
  // s15Fixed16Number (§4.6): round to the nearest 1/65536.
  void s15f16(double v) { u32(static_cast<std::uint32_t>(static_cast<std::int32_t>(std::lround(v * 65536.0)))); }
  void pad4() {
    while (bytes.size() % 4) u8(0);
  }
  void put_u32(std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes[at + i] = static_cast<std::uint8_t>(v >> (24 - 8 * i));
  }
  std::vector<std::uint8_t> bytes;
};

// multiLocalizedUnicodeType (§10.15) with one en-US record, UTF-16BE (ASCII input).
std::vector<std::uint8_t> mluc(const std::string& text) {
  IccWriter w;
  w.signature("mluc");
  w.u32(0);
  w.u32(1);   // records
  w.u32(12);  // record size
  w.signature("enUS");
  w.u32(static_cast<std::uint32_t>(2 * text.size()));
  w.u32(28);  // offset of the string from the start of the tag
  for (char c : text) w.u16(static_cast<std::uint8_t>(c) < 0x80 ? static_cast<std::uint16_t>(c) : u'?');
  return w.bytes;
}

std::vector<std::uint8_t> xyz_tag(const Vec3d& xyz) {
  IccWriter w;
  w.signature("XYZ ");
  w.u32(0);
  w.s15f16(xyz.x), w.s15f16(xyz.y), w.s15f16(xyz.z);
  return w.bytes;
}

std::vector<std::uint8_t> sf32_tag(const Mat3& m) {
  IccWriter w;
  w.signature("sf32");
  w.u32(0);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) w.s15f16(m.m[r][c]);
  return w.bytes;
}

// parametricCurveType (§10.18).
std::vector<std::uint8_t> para_tag(IccToneCurve curve) {
  IccWriter w;
  w.signature("para");
  w.u32(0);
  switch (curve) {
    case IccToneCurve::srgb:
      // Y = (aX + b)^g for X >= d, Y = cX below (IEC 61966-2-1 decoding).
      w.u16(3), w.u16(0);
      w.s15f16(2.4), w.s15f16(1.0 / 1.055), w.s15f16(0.055 / 1.055), w.s15f16(1.0 / 12.92), w.s15f16(0.04045);
      break;
    case IccToneCurve::gamma_2_4:
      w.u16(0), w.u16(0), w.s15f16(2.4);
      break;
    case IccToneCurve::gamma_2_2:
      w.u16(0), w.u16(0), w.s15f16(563.0 / 256.0);
      break;
    case IccToneCurve::gamma_2_6:
      w.u16(0), w.u16(0), w.s15f16(2.6);
      break;
  }
  return w.bytes;
}

}  // namespace

Vec3d icc_pcs_illuminant_XYZ() { return {0.9642, 1.0, 0.8249}; }

Mat3 icc_colorant_matrix(const ColorSpace& space) {
  return adaptation_matrix(white_XYZ(space), icc_pcs_illuminant_XYZ(), Cat::bradford) * space.rgb_to_xyz;
}

std::vector<std::uint8_t> make_icc_display_profile(const ColorSpace& space, IccToneCurve curve,
                                                   const std::string& description) {
  const Mat3 chad = adaptation_matrix(white_XYZ(space), icc_pcs_illuminant_XYZ(), Cat::bradford);
  const Mat3 colorants = icc_colorant_matrix(space);
  const auto column = [&](int c) { return Vec3d(colorants.m[0][c], colorants.m[1][c], colorants.m[2][c]); };

  struct Tag {
    char signature[5];
    std::vector<std::uint8_t> data;
    int shares = -1;  // index of an earlier tag whose data this one points at
  };
  std::vector<Tag> tags = {
      {"desc", mluc(description)},
      {"cprt", mluc("No copyright, use freely")},
      {"wtpt", xyz_tag(icc_pcs_illuminant_XYZ())},
      {"chad", sf32_tag(chad)},
      {"rXYZ", xyz_tag(column(0))},
      {"gXYZ", xyz_tag(column(1))},
      {"bXYZ", xyz_tag(column(2))},
      {"rTRC", para_tag(curve)},
      {"gTRC", {}, 7},
      {"bTRC", {}, 7},
  };

  IccWriter w;
  // Header (§7.2), 128 bytes; the size is patched in at the end.
  w.u32(0);
  w.u32(0);                    // preferred CMM: none
  w.u32(0x04400000);           // version 4.4.0.0
  w.signature("mntr");         // display device
  w.signature("RGB ");
  w.signature("XYZ ");         // PCS
  for (std::uint16_t v : {2026, 1, 1, 0, 0, 0}) w.u16(v);  // fixed creation date (UTC)
  w.signature("acsp");
  w.u32(0);                    // primary platform: none
  w.u32(0);                    // flags
  w.u32(0), w.u32(0);          // device manufacturer, model
  w.u32(0), w.u32(0);          // device attributes
  w.u32(0);                    // rendering intent: perceptual
  const Vec3d d50 = icc_pcs_illuminant_XYZ();
  w.s15f16(d50.x), w.s15f16(d50.y), w.s15f16(d50.z);
  w.signature("PRSM");         // profile creator
  for (int i = 0; i < 16; ++i) w.u8(0);  // profile ID: not calculated
  for (int i = 0; i < 28; ++i) w.u8(0);  // reserved

  // Tag table (§7.3), then the tag data, each element 4-byte aligned.
  w.u32(static_cast<std::uint32_t>(tags.size()));
  const std::size_t table = w.bytes.size();
  for (std::size_t i = 0; i < tags.size(); ++i) {
    w.signature(tags[i].signature);
    w.u32(0), w.u32(0);
  }
  std::vector<std::uint32_t> offset(tags.size()), size(tags.size());
  for (std::size_t i = 0; i < tags.size(); ++i) {
    if (tags[i].shares >= 0) {
      offset[i] = offset[static_cast<std::size_t>(tags[i].shares)];
      size[i] = size[static_cast<std::size_t>(tags[i].shares)];
      continue;
    }
    w.pad4();
    offset[i] = static_cast<std::uint32_t>(w.bytes.size());
    size[i] = static_cast<std::uint32_t>(tags[i].data.size());
    w.bytes.insert(w.bytes.end(), tags[i].data.begin(), tags[i].data.end());
  }
  w.pad4();
  for (std::size_t i = 0; i < tags.size(); ++i) {
    w.put_u32(table + 12 * i + 4, offset[i]);
    w.put_u32(table + 12 * i + 8, size[i]);
  }
  w.put_u32(0, static_cast<std::uint32_t>(w.bytes.size()));
  return w.bytes;
}

}  // namespace prism::color
