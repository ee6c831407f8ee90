// What a Radiance picture's header says its texels are (io/radiance_hdr_reader.h), applied when
// it is read as a colour texture (scene/texture_file.h): a PRIMARIES line is the texels'
// colour space (an environment keeps it, as an OpenEXR sky keeps its chromaticities), XYZE
// texels are CIE XYZ relative to the equal-energy white, and EXPOSURE and COLORCORR are
// factors the texels were multiplied by. A reader that ignored the header, taking every
// .hdr for Rec.709 radiance, fails these tests.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include <stb_image_write.h>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/color_space.h"
#include "prism/core/memory_budget.h"
#include "prism/scene/emission.h"
#include "prism/scene/environment_override.h"
#include "prism/scene/loaders/json_scene.h"
#include "prism/scene/loaders/pbrt_scene.h"
#include "prism/io/radiance_hdr_reader.h"
#include "prism/scene/texture_file.h"
#include "scene/loaders/loader_test_files.h"

namespace prism {
namespace {

// Texel values exact in RGBE (an 8-bit mantissa and a power of two): the file holds
// exactly these, so every expectation below is the arithmetic on them alone.
const std::vector<float> kTexels = {0.5f, 0.25f, 0.125f,  0.75f, 0.5f, 0.0f,  1.0f, 1.0f, 1.0f,  0.0f, 0.0f, 0.0f};
constexpr int kWidth = 2, kHeight = 2;  // below 8: flat texels

// A .hdr of kTexels written by stb_image_write, with `lines` put into its header and its
// FORMAT line replaced by `format`.
std::string hdr_with_header(const std::string& lines, const std::string& format = "32-bit_rle_rgbe") {
  std::string file;
  stbi_write_hdr_to_func([](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
  }, &file, kWidth, kHeight, 3, kTexels.data());
  const std::string stb_format = "FORMAT=32-bit_rle_rgbe\n";
  const std::size_t at = file.find(stb_format);
  EXPECT_NE(at, std::string::npos);
  return file.replace(at, stb_format.size(), lines + "FORMAT=" + format + "\n");
}

const std::string kRec2020Primaries = "PRIMARIES=0.708 0.292 0.170 0.797 0.131 0.046 0.3127 0.3290\n";

TextureImage read_as(const std::filesystem::path& path, TextureContent content, MemoryBudget* budget = nullptr) {
  return read_texture_file(path, TextureEncoding::linear, TextureLimits(64, budget), content);
}

// kTexels through `m`, as float texels.
std::vector<float> transformed(const Mat3& m, bool clip) {
  std::vector<float> out;
  for (std::size_t t = 0; t < kTexels.size(); t += 3) {
    const Vec3d v = m * Vec3d(kTexels[t], kTexels[t + 1], kTexels[t + 2]);
    for (int k = 0; k < 3; ++k) out.push_back(static_cast<float>(clip ? std::max(v[k], 0.0) : v[k]));
  }
  return out;
}

// Float texels against expected ones: the conversion runs in double on the same numbers and
// rounds once to float, so they agree to float's rounding (1 ulp, 6e-8 relative, and an
// absolute 1e-7 where a channel cancels to 0).
void expect_texels(const TextureImage& t, const std::vector<float>& expected) {
  const std::vector<float> got = t.linear_values();
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i)
    EXPECT_NEAR(got[i], expected[i], 6e-8 * std::abs(expected[i]) + 1e-7) << "sample " << i;
}

TEST(RadianceHdrColor, APrimariesLineIsTheTexelsColourSpace) {
  test::ScratchFolder dir;
  dir.write("rec2020.hdr", hdr_with_header(kRec2020Primaries));
  // In its own gamut (an environment map): Rec.2020, the RGBE texels kept as written.
  const TextureImage own = read_as(dir / "rec2020.hdr", TextureContent::color_own_gamut);
  EXPECT_EQ(own.texel_space, ColorPickerSpace::rec2020);
  EXPECT_TRUE(own.has_rgbe());
  EXPECT_EQ(own.linear_values(), kTexels);
  EXPECT_EQ(own.primaries_note, "");
  // Into ACEScg (an ACEScg material's base colour): converted, Bradford between whites.
  const TextureImage aces = read_as(dir / "rec2020.hdr", TextureContent::color_acescg);
  EXPECT_EQ(aces.texel_space, ColorPickerSpace::acescg);
  EXPECT_FALSE(aces.has_rgbe());
  expect_texels(aces, transformed(color::conversion_matrix(color::color_space("rec2020"), color::color_space("acescg")),
                                  false));
  EXPECT_NE(aces.primaries_note.find("RGB in the primaries of its PRIMARIES line (red 0.7080,0.2920"), std::string::npos)
      << aces.primaries_note;
  // Into Rec.709 (an sRGB material): what lies outside is clipped and counted. The
  // saturated texel (0.75, 0.5, 0) has a negative Rec.709 blue (−0.0182·0.75 − 0.1006·0.5,
  // BT.2087's matrix); the others lie inside.
  const TextureImage srgb = read_as(dir / "rec2020.hdr", TextureContent::color);
  EXPECT_EQ(srgb.texel_space, ColorPickerSpace::srgb);
  expect_texels(srgb, transformed(color::conversion_matrix(color::color_space("rec2020"), color::color_space("srgb")),
                                  true));
  EXPECT_NE(srgb.primaries_note.find("converted to Rec.709; 1 of 4 texels lie outside Rec.709"), std::string::npos)
      << srgb.primaries_note;
  // Data is read as stored.
  const TextureImage data = read_as(dir / "rec2020.hdr", TextureContent::data);
  EXPECT_TRUE(data.has_rgbe());
  EXPECT_EQ(data.linear_values(), kTexels);
}

// Without a PRIMARIES line, with Photoshop's all-zero one, or with Rec.709's own, a file is
// Rec.709 and read exactly as before: RGBE kept, no note, in every content.
TEST(RadianceHdrColor, FilesWithoutPrimariesAreRec709AsBefore) {
  test::ScratchFolder dir;
  dir.write("plain.hdr", hdr_with_header(""));
  dir.write("photoshop.hdr", hdr_with_header("GAMMA=1\nPRIMARIES=0 0 0 0 0 0 0 0\n"));
  dir.write("rec709.hdr", hdr_with_header("PRIMARIES= 0.640 0.330 0.300 0.600 0.150 0.060 0.3127 0.3290\nEXPOSURE=1\n"));
  for (const char* file : {"plain.hdr", "photoshop.hdr", "rec709.hdr"}) {
    for (TextureContent content : {TextureContent::color, TextureContent::color_own_gamut}) {
      const TextureImage t = read_as(dir / file, content);
      EXPECT_EQ(t.texel_space, ColorPickerSpace::srgb) << file;
      EXPECT_TRUE(t.has_rgbe()) << file;
      EXPECT_EQ(t.linear_values(), kTexels) << file;
      EXPECT_EQ(t.primaries_note, "") << file;
    }
    EXPECT_EQ(texture_file_memory_need(dir / file)->texel_bytes, 4u * kWidth * kHeight) << file;
  }
}

// EXPOSURE and COLORCORR are what the texels were multiplied by (cumulative): radiance is
// the texel divided by their product, channel by channel.
TEST(RadianceHdrColor, ExposureAndColorCorrectionAreDividedOut) {
  test::ScratchFolder dir;
  dir.write("exposed.hdr", hdr_with_header("EXPOSURE=2\nEXPOSURE=2\nCOLORCORR=1 2 0.5\n"));
  MemoryBudget budget(0);
  const TextureImage t = read_as(dir / "exposed.hdr", TextureContent::color_own_gamut, &budget);
  EXPECT_EQ(t.texel_space, ColorPickerSpace::srgb);
  std::vector<float> expected = kTexels;
  for (std::size_t i = 0; i < expected.size(); ++i) expected[i] /= std::array<float, 3>{4.0f, 8.0f, 2.0f}[i % 3];
  EXPECT_EQ(t.linear_values(), expected);  // divisions by powers of two: exact
  EXPECT_NE(t.primaries_note.find("Rec.709 RGB kept in Rec.709, divided by its header's EXPOSURE 4 and COLORCORR 1 2 0.5 to radiance"),
            std::string::npos)
      << t.primaries_note;
  // Float texels, 12 bytes each, charged to the budget; the header alone says as much.
  EXPECT_EQ(budget.used_bytes(), 12u * kWidth * kHeight);
  const auto need = texture_file_memory_need(dir / "exposed.hdr");
  EXPECT_EQ(need->texel_bytes, 12u * kWidth * kHeight);
  EXPECT_EQ(need->transient_bytes, 4u * kWidth * kHeight);
  // Data keeps the numbers as stored.
  EXPECT_EQ(read_as(dir / "exposed.hdr", TextureContent::data).linear_values(), kTexels);
  // With primaries that are the target's, only the factor applies.
  dir.write("rec2020_exposed.hdr", hdr_with_header(kRec2020Primaries + "EXPOSURE=0.5\n"));
  const TextureImage wide = read_as(dir / "rec2020_exposed.hdr", TextureContent::color_own_gamut);
  EXPECT_EQ(wide.texel_space, ColorPickerSpace::rec2020);
  std::vector<float> doubled = kTexels;
  for (float& v : doubled) v *= 2.0f;
  EXPECT_EQ(wide.linear_values(), doubled);
  EXPECT_NE(wide.primaries_note.find("kept in Rec.2020, divided by its header's EXPOSURE 0.5 to radiance"),
            std::string::npos)
      << wide.primaries_note;
}

// XYZE texels are CIE XYZ. Radiance holds XYZ relative to the equal-energy white (its RGB
// white (1, 1, 1) is XYZ (1, 1, 1)), so that XYZ is each target space's white, (1, 1, 1),
// and every texel is the target's XYZ → RGB after Bradford from E to the target's white.
// XYZ lies outside every RGB gamut, so in its own gamut it goes to the widest, ACEScg.
TEST(RadianceHdrColor, XyzeTexelsAreXyzRelativeToTheEqualEnergyWhite) {
  test::ScratchFolder dir;
  dir.write("xyz.hdr", hdr_with_header("", "32-bit_rle_xyze"));
  const Vec3d e_white(1.0, 1.0, 1.0);
  for (const auto& [content, space, name] :
       {std::tuple{TextureContent::color_own_gamut, ColorPickerSpace::acescg, "acescg"},
        std::tuple{TextureContent::color, ColorPickerSpace::srgb, "srgb"},
        std::tuple{TextureContent::color_rec2020, ColorPickerSpace::rec2020, "rec2020"}}) {
    const TextureImage t = read_as(dir / "xyz.hdr", content);
    EXPECT_EQ(t.texel_space, space) << name;
    const std::vector<float> v = t.linear_values();
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(v[6 + k], 1.0f, 1e-6f) << name << " white, channel " << k;
    const color::ColorSpace& target = color::color_space(name);
    const Mat3 expected = target.xyz_to_rgb * color::adaptation_matrix(e_white, color::white_XYZ(target));
    expect_texels(t, transformed(expected, true));
    EXPECT_NE(t.primaries_note.find(std::string("CIE XYZ (FORMAT=32-bit_rle_xyze) converted to ") +
                                    picker_space_label(space)),
              std::string::npos)
        << t.primaries_note;
  }
}

// The whole-image reader (`prism tonemap IN.hdr`): float radiance, the factors divided out,
// with the space the header names.
TEST(RadianceHdrColor, WholeImagesComeWithTheirSpaceAndWithoutTheirFactors) {
  const auto as_span = [](const std::string& s) {
    return std::span<const unsigned char>(reinterpret_cast<const unsigned char*>(s.data()), s.size());
  };
  const RadianceImage wide = read_radiance_image(as_span(hdr_with_header(kRec2020Primaries + "EXPOSURE=4\n")), "w.hdr");
  EXPECT_EQ(wide.width, kWidth);
  EXPECT_EQ(wide.height, kHeight);
  std::vector<float> quarter = kTexels;
  for (float& v : quarter) v /= 4.0f;
  EXPECT_EQ(wide.rgb, quarter);
  EXPECT_EQ(wide.space.red.x, 0.708);
  EXPECT_EQ(wide.space.white.y, 0.3290);
  EXPECT_EQ(read_radiance_image(as_span(hdr_with_header("")), "p.hdr").space.name, "srgb");
  const RadianceImage xyz = read_radiance_image(as_span(hdr_with_header("", "32-bit_rle_xyze")), "x.hdr");
  EXPECT_EQ(xyz.rgb, kTexels);
  EXPECT_EQ(xyz.space.rgb_to_xyz(0, 0), 1.0);
  EXPECT_EQ(xyz.space.white.x, 1.0 / 3.0);
}

// A JSON scene's, a pbrt-v4 infinite light's and --environment's .hdr sky with a PRIMARIES
// line is held in its own gamut, as an OpenEXR sky is; what the header's factors did is
// among the scene's warnings.
TEST(RadianceHdrColor, EnvironmentMapsKeepTheirPrimariesAndSayWhatTheirHeaderDid) {
  test::ScratchFolder dir;
  dir.write("rec2020.hdr", hdr_with_header(kRec2020Primaries));
  dir.write("exposed.hdr", hdr_with_header("EXPOSURE=4\n"));
  const auto sky = [](const Scene& scene) -> const TextureImage& {
    for (const Light& l : scene.lights)
      if (l.type == LightType::environment && l.environment_texture >= 0)
        return scene.textures[static_cast<std::size_t>(l.environment_texture)];
    throw std::runtime_error("no environment map");
  };
  const auto json = [&](const std::string& file) {
    return loaders::parse_json_scene(R"({"format": "prism-scene/1",
      "materials": [{"name": "grey", "type": "diffuse", "base_color": [0.5, 0.5, 0.5]}],
      "meshes": [{"name": "floor", "material": "grey", "positions": [[-1, 0, -1], [1, 0, -1], [1, 0, 1]],
                  "indices": [0, 2, 1]}],
      "camera": {"eye": [0, 1, 0], "target": [0, 0, 0], "up": [0, 0, 1], "fov_degrees": 30},
      "environment": {"texture": ")" + file + R"(", "luminance_nits": 1}})",
                                     "sky.json", dir.path(), "sky");
  };
  const auto pbrt = [&](const std::string& file) {
    return loaders::parse_pbrt_scene("WorldBegin\nLightSource \"infinite\" \"string filename\" \"" + file +
                                         "\"\nShape \"sphere\"\n",
                                     "sky.pbrt", dir.path());
  };
  const auto overridden = [&](const std::string& file) {
    Scene s = json("exposed.hdr");
    s.warnings.clear();
    apply_environment_override(s, EnvironmentOverride{(dir / file).string(), 1.0f, 0.0f});
    return s;
  };
  for (const Scene& s : {json("rec2020.hdr"), pbrt("rec2020.hdr"), overridden("rec2020.hdr")}) {
    EXPECT_EQ(sky(s).texel_space, ColorPickerSpace::rec2020);
    EXPECT_EQ(sky(s).linear_values(), kTexels);
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
  }
  for (const Scene& s : {json("exposed.hdr"), pbrt("exposed.hdr"), overridden("exposed.hdr")}) {
    EXPECT_EQ(sky(s).linear_values()[0], 0.125f);  // 0.5 / 4
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("divided by its header's EXPOSURE 4 to radiance"), std::string::npos) << s.warnings[0];
  }
}

}  // namespace
}  // namespace prism
