#pragma once
// HDR10 static metadata: SMPTE ST 2086 mastering display colour volume and the CTA-861.3
// content light levels (MaxCLL, MaxFALL), with their PNG Third Edition (W3C 2025) chunk
// byte layouts (cICP §11.3.2.6, mDCv §11.3.2.7, cLLi §11.3.2.8).
#include <array>
#include <cstdint>
#include <vector>

namespace prism {

// ITU-T H.273 code points as stored in cICP.
struct CicpInfo {
  std::uint8_t color_primaries = 9;           // 1 BT.709, 9 BT.2020, 12 P3-D65 (SMPTE EG 432)
  std::uint8_t transfer_characteristics = 16; // 1 BT.709/1886, 13 sRGB, 16 PQ (ST 2084)
  std::uint8_t matrix_coefficients = 0;       // PNG requires 0 (RGB)
  std::uint8_t video_full_range = 1;
};

struct MasteringDisplay {
  double red_x, red_y, green_x, green_y, blue_x, blue_y, white_x, white_y;
  double max_luminance_nits, min_luminance_nits;
};

struct ContentLightLevel {
  double max_cll_nits = 0;   // brightest pixel's max(R, G, B)
  double max_fall_nits = 0;  // frame average of max(R, G, B)
};

// CTA-861.3 Annex A on one frame of display-linear RGB in nits (3 per pixel): per pixel
// max(R, G, B) (negatives count as 0), MaxCLL its maximum, MaxFALL its mean.
ContentLightLevel content_light_level(const std::vector<float>& rgb_nits);

// Chunk payloads, big-endian as PNG requires.
std::array<std::uint8_t, 4> cicp_chunk_data(const CicpInfo& c);
// Chromaticities in units of 0.00002 (R, G, B, then white), luminances in 0.0001 cd/m².
std::array<std::uint8_t, 24> mdcv_chunk_data(const MasteringDisplay& m);
// MaxCLL then MaxFALL, each in 0.0001 cd/m² (uint32).
std::array<std::uint8_t, 8> clli_chunk_data(const ContentLightLevel& c);

}  // namespace prism
