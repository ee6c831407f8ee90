// PNG and JPEG colour tags (scene/image_color_tags.h) applied when an image is read as a
// colour texture (scene/texture_file.h): cICP, an embedded ICC profile (PNG iCCP, JPEG
// APP2), the sRGB chunk, cHRM and gAMA. Read as sRGB whatever it says, a Display P3
// texture renders desaturated; these tests fail if the tags are ignored.
//
// The files in data/color_tags were written by Little CMS 2 (the ICC profiles) and Pillow
// (the images), both independent of Prism (scripts/testdata/icc_texture_oracle.c and
// icc_texture_images.py). The expected values are lcms2's relative-colorimetric transform
// of the same codes into linear Rec.709 or ACEScg, printed by icc_texture_oracle.c.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "prism/color/icc_profile.h"
#include "prism/color/icc_profile_reader.h"
#include "prism/color/transfer_functions.h"
#include "prism/core/error.h"
#include "prism/core/memory_budget.h"
#include "prism/io/read_to_end.h"
#include "prism/scene/image_color_tags.h"
#include "prism/scene/loaders/json_scene.h"
#include "prism/scene/texture_file.h"
#include "scene/loaders/loader_test_files.h"

namespace prism {
namespace {

const std::filesystem::path kColorTagsData = std::filesystem::path(PRISM_SOURCE_DIR) / "tests/scene/loaders/data/color_tags";

// The row of codes every RGB image holds (icc_texture_images.py's ROW).
constexpr int kRow = 8;
using Oracle = std::array<std::array<double, 3>, kRow>;

// lcms2 2.14, INTENT_RELATIVE_COLORIMETRIC, cmsFLAGS_NOOPTIMIZE (icc_texture_oracle.c).
constexpr Oracle kP3TableToRec709 = {{{1.2249402, -0.0420570, -0.0196376}, {-0.2249402, 1.0420569, -0.0786360},
                                      {0.0, 0.0, 1.0982736}, {0.6788207, 0.1085124, 0.0136617},
                                      {0.2158541, 0.2158541, 0.2158541}, {0.0021441, 0.0071707, 0.0136512},
                                      {1.0, 1.0, 1.0}, {0.0, 0.0, 0.0}}};
constexpr Oracle kP3TableToAcescg = {{{0.7357979, 0.0471799, 0.0035637}, {0.2121665, 0.9380457, 0.0411419},
                                      {0.0520356, 0.0147744, 0.9552944}, {0.4536729, 0.1472685, 0.0377672},
                                      {0.2158541, 0.2158541, 0.2158541}, {0.0043960, 0.0069051, 0.0127039},
                                      {1.0, 1.0, 1.0}, {0.0, 0.0, 0.0}}};
constexpr Oracle kRec2020Gamma22ToRec709 = {{{1.6604910, -0.1245505, -0.0181508}, {-0.5876411, 1.1328999, -0.1005789},
                                             {-0.0728499, -0.0083494, 1.1187297}, {0.8960392, 0.0712635, 0.0075880},
                                             {0.2195197, 0.2195197, 0.2195197}, {-0.0014937, 0.0040131, 0.0097061},
                                             {1.0, 1.0, 1.0}, {0.0, 0.0, 0.0}}};
constexpr Oracle kRec2020Gamma18ToRec709 = {{{1.6604910, -0.1245505, -0.0181508}, {-0.5876411, 1.1328999, -0.1005789},
                                             {-0.0728499, -0.0083494, 1.1187297}, {0.9594467, 0.1292204, 0.0292061},
                                             {0.2892049, 0.2892049, 0.2892049}, {-0.0026809, 0.0110517, 0.0226731},
                                             {1.0, 1.0, 1.0}, {0.0, 0.0, 0.0}}};
constexpr std::array<double, 3> kP3LargeTablesToRec709At200_100_50 = {0.6788428, 0.1084959, 0.0136626};

TextureImage read_color(const std::string& file, TextureContent content = TextureContent::color,
                        MemoryBudget* budget = nullptr) {
  return read_texture_file(kColorTagsData / file, TextureEncoding::srgb, TextureLimits(64, budget), content);
}

// The file decoded as a glTF image is: its tags ignored.
TextureImage read_ignoring_tags(const std::string& file) {
  return decode_texture_memory(read_file_bytes(kColorTagsData / file, "image"), file, TextureEncoding::srgb, TextureLimits(64),
                               TextureContent::color, ImageColorTagUse::ignore);
}

// Tolerance: the texels are half floats (relative precision 2^-11 = 4.9e-4), and the two
// implementations round the colorants differently (lcms2 through its s15Fixed16 tags and
// its own Bradford, Prism in double): 1e-3 relative, and 2e-5 absolute near black.
void expect_texel(const TextureImage& t, int texel, const std::array<double, 3>& expected, bool clip,
                  const std::string& what) {
  for (int k = 0; k < 3; ++k) {
    const double e = clip ? std::max(expected[static_cast<std::size_t>(k)], 0.0) : expected[static_cast<std::size_t>(k)];
    EXPECT_NEAR(t.value(static_cast<std::size_t>(texel * t.channels + k)), e, 1e-3 * std::abs(e) + 2e-5)
        << what << " texel " << texel << " channel " << k;
  }
}
void expect_row(const TextureImage& t, const Oracle& oracle, bool clip, const std::string& what) {
  ASSERT_EQ(t.width, kRow);
  ASSERT_EQ(t.channels, 3);
  for (int i = 0; i < kRow; ++i) expect_texel(t, i, oracle[static_cast<std::size_t>(i)], clip, what);
}

TEST(ImageColorTags, DisplayP3IccProfileDecodesToLcmsValues) {
  // A version 2 profile with 1024-entry tone tables and a textDescriptionType.
  const TextureImage rec709 = read_color("display-p3-icc.png");
  EXPECT_TRUE(rec709.has_halves());
  EXPECT_EQ(rec709.texel_space, ColorPickerSpace::srgb);
  expect_row(rec709, kP3TableToRec709, /*clip=*/true, "P3 to Rec.709");
  // P3's red and green lie outside Rec.709 (and 10,20,30 does not): clipped and said.
  EXPECT_NE(rec709.primaries_note.find("ICC profile 'Display P3 (lcms2, tables)' decoded and converted to Rec.709"),
            std::string::npos)
      << rec709.primaries_note;
  EXPECT_NE(rec709.primaries_note.find("2 of 8 texels lie outside Rec.709"), std::string::npos) << rec709.primaries_note;

  // A wide-gamut base colour keeps them: ACEScg holds P3.
  const TextureImage acescg = read_color("display-p3-icc.png", TextureContent::color_acescg);
  EXPECT_EQ(acescg.texel_space, ColorPickerSpace::acescg);
  expect_row(acescg, kP3TableToAcescg, /*clip=*/false, "P3 to ACEScg");
  EXPECT_EQ(acescg.primaries_note.find("clipped"), std::string::npos) << acescg.primaries_note;
  // A sky or a pbrt-v4 image texture keeps the smallest space that holds its gamut: P3's
  // red (0.680, 0.320) lies just outside Rec.2020's red–green edge (y = 0.318 at x = 0.680),
  // so ACEScg; a Rec.2020 image stays in Rec.2020.
  EXPECT_EQ(read_color("display-p3-icc.png", TextureContent::color_own_gamut).texel_space, ColorPickerSpace::acescg);
  EXPECT_EQ(read_color("rec2020-gamma22-icc.png", TextureContent::color_own_gamut).texel_space,
            ColorPickerSpace::rec2020);
}

TEST(ImageColorTags, PowerLawIccProfileDecodesToLcmsValues) {
  // Version 4, a curveType of one entry (gamma 2.2 in u8Fixed8), Rec.2020 primaries.
  expect_row(read_color("rec2020-gamma22-icc.png"), kRec2020Gamma22ToRec709, true, "Rec.2020 gamma 2.2");
}

TEST(ImageColorTags, CicpAndChrmGamaDecodeLikeTheProfilesTheyName) {
  // cICP 12/13/0/1 is Display P3 with the sRGB curve: lcms2's P3 table profile samples that
  // curve at 1024 codes (within 1e-5 of it between them), inside the tolerance.
  const TextureImage cicp = read_color("display-p3-cicp.png");
  expect_row(cicp, kP3TableToRec709, true, "cICP P3");
  EXPECT_NE(cicp.primaries_note.find("cICP 12/13/0/1"), std::string::npos) << cicp.primaries_note;
  // cHRM of Rec.2020 and gAMA 55556 (1/1.79998) against lcms2 at 1/1.8 exactly: the
  // exponents differ by 1e-5 relative, which moves no value by more than 3e-6.
  expect_row(read_color("rec2020-gamma18-chrm.png"), kRec2020Gamma18ToRec709, true, "cHRM + gAMA");
}

TEST(ImageColorTags, SrgbImagesKeepTheirCodes) {
  // lcms2's own sRGB profile (parametric curves, its Bradford colorants), and the sRGB
  // chunk with the gAMA 45455 an sRGB encoder writes beside it: the codes stay, decoded by
  // the sRGB table at lookup, with nothing to warn about.
  for (const char* file : {"srgb-icc.png", "srgb-chunk.png"}) {
    const TextureImage t = read_color(file);
    EXPECT_TRUE(t.has_codes()) << file;
    EXPECT_EQ(t.texel_space, ColorPickerSpace::srgb) << file;
    EXPECT_EQ(t.primaries_note, "") << file;
    EXPECT_FLOAT_EQ(t.value(3 * 3), static_cast<float>(color::srgb_decode(200 / 255.0))) << file;
  }
}

TEST(ImageColorTags, GreyIccProfileDecodesItsCurve) {
  const TextureImage t = read_color("gray-gamma18-icc.png");
  ASSERT_EQ(t.channels, 1);
  EXPECT_TRUE(t.has_halves());
  EXPECT_EQ(t.texel_space, ColorPickerSpace::srgb);
  // lcms2 writes a version 4 grey profile's 1.8 as a parametricCurveType of function 0, in
  // s15Fixed16 (1.8 + 3e-6); half floats: 4.9e-4 relative.
  const std::array<int, 6> codes = {0, 10, 50, 128, 200, 255};
  for (std::size_t i = 0; i < codes.size(); ++i) {
    const double e = std::pow(codes[i] / 255.0, 1.8);
    EXPECT_NEAR(t.value(i), e, 1e-3 * e + 1e-6) << codes[i];
  }
  EXPECT_NE(t.primaries_note.find("(grey)"), std::string::npos) << t.primaries_note;
}

TEST(ImageColorTags, JpegProfileOverTwoApp2SegmentsIsRead) {
  // 98 kB of profile, which Pillow split into two APP2 segments; every pixel is the code
  // 200,100,50 (quality 100, 4:4:4: the decode without tags checks that premise first).
  const TextureImage codes = read_ignoring_tags("display-p3-large-icc.jpg");
  ASSERT_TRUE(codes.has_codes());
  for (std::size_t i = 0; i < codes.codes.size(); i += 3)
    ASSERT_TRUE(codes.codes[i] == 200 && codes.codes[i + 1] == 100 && codes.codes[i + 2] == 50) << i;
  const TextureImage t = read_color("display-p3-large-icc.jpg");
  ASSERT_EQ(t.width * t.height, 256);
  for (int i = 0; i < 256; i += 51) expect_texel(t, i, kP3LargeTablesToRec709At200_100_50, true, "JPEG");
  EXPECT_NE(t.primaries_note.find("Display P3 (lcms2, large tables)"), std::string::npos) << t.primaries_note;
}

TEST(ImageColorTags, GltfImagesAndDataTexturesIgnoreTags) {
  // glTF 2.0 §3.8.3: colour information in its PNG and JPEG images MUST be ignored.
  const TextureImage gltf = read_ignoring_tags("display-p3-icc.png");
  EXPECT_TRUE(gltf.has_codes());
  EXPECT_EQ(gltf.primaries_note, "");
  // Data (a roughness or normal map) is read as stored whatever it says.
  const TextureImage data =
      read_texture_file(kColorTagsData / "display-p3-icc.png", TextureEncoding::linear, TextureLimits(64), TextureContent::data);
  EXPECT_TRUE(data.has_codes());
  EXPECT_FLOAT_EQ(data.value(3 * 3), 200.0f / 255.0f);
}

TEST(ImageColorTags, PqAndHlgAreRefusedWithTheFileNamed) {
  try {
    read_color("pq-cicp.png");
    FAIL() << "a PQ texture was read";
  } catch (const IoError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("pq-cicp.png"), std::string::npos) << what;
    EXPECT_NE(what.find("cICP 9/16/0/1 says PQ"), std::string::npos) << what;
  }
}

TEST(ImageColorTags, UnreadableTagsArePassedOverAndSaid) {
  // An iCCP chunk whose data is not zlib: the image is read as sRGB (the next tag in
  // precedence, here none), and the note says why.
  const TextureImage t = read_color("corrupt-iccp.png");
  EXPECT_TRUE(t.has_codes());
  EXPECT_NE(t.primaries_note.find("iCCP chunk ignored (its compressed profile is corrupt or cut short); read as sRGB"),
            std::string::npos)
      << t.primaries_note;
}

TEST(ImageColorTags, ProfilesOfLookupTablesAndOtherSpacesAreRefusedWithTheReason) {
  // Prism's own display profile writer (color/icc_profile.h) as a base, with tags renamed.
  std::vector<std::uint8_t> profile =
      color::make_icc_display_profile(color::color_space("display-p3"), color::IccToneCurve::srgb, "P3");
  EXPECT_NO_THROW(color::read_icc_matrix_trc(profile));
  const auto refusal = [](std::vector<std::uint8_t> p) -> std::string {
    try {
      color::read_icc_matrix_trc(p);
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  };
  // No rXYZ tag: what a profile of lookup tables alone looks like to the matrix/TRC model.
  std::vector<std::uint8_t> no_matrix = profile;
  const std::uint32_t count = (no_matrix[128] << 24) | (no_matrix[129] << 16) | (no_matrix[130] << 8) | no_matrix[131];
  for (std::uint32_t i = 0; i < count; ++i)
    if (std::equal(no_matrix.begin() + 132 + 12 * i, no_matrix.begin() + 136 + 12 * i, "rXYZ"))
      no_matrix[132 + 12 * i] = 'A';
  EXPECT_NE(refusal(no_matrix).find("no rXYZ tag"), std::string::npos) << refusal(no_matrix);
  std::vector<std::uint8_t> cmyk = profile;
  std::copy_n("CMYK", 4, cmyk.begin() + 16);
  EXPECT_NE(refusal(cmyk).find("not RGB or grey"), std::string::npos);
  std::vector<std::uint8_t> not_icc = profile;
  not_icc[36] = 'x';
  EXPECT_EQ(refusal(not_icc), "not an ICC profile");
  // A tag that points past the end.
  std::vector<std::uint8_t> cut(profile.begin(), profile.end() - 16);
  cut[0] = cut[1] = 0, cut[2] = static_cast<std::uint8_t>(cut.size() >> 8), cut[3] = static_cast<std::uint8_t>(cut.size());
  EXPECT_NE(refusal(cut).find("runs past the profile's end"), std::string::npos) << refusal(cut);
}

TEST(ImageColorTags, PrismsOwnProfilesRoundTrip) {
  // What `prism render -o x.png --display-primaries p3` embeds reads back as its space.
  for (const char* space : {"display-p3", "adobe-rgb", "rec2020"}) {
    const color::ColorSpace& s = color::color_space(space);
    const color::IccMatrixTrc p =
        color::read_icc_matrix_trc(color::make_icc_display_profile(s, color::IccToneCurve::gamma_2_2, space));
    const Mat3 expected = color::icc_colorant_matrix(s);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(p.colorants.m[i][j], expected.m[i][j], 1.0 / 65536) << space;  // s15Fixed16
    EXPECT_EQ(p.description, space);
    EXPECT_NEAR(p.curves[1](0.5), std::pow(0.5, 563.0 / 256.0), 1e-4) << space;
  }
}

TEST(ImageColorTags, FilesWithTagsAreFoundFromTheirHeadersAlone) {
  // The texture cache keys a tagged image by its use (a Rec.709 and an ACEScg base colour
  // get their own texels) and an untagged one once.
  for (const char* file : {"display-p3-icc.png", "display-p3-cicp.png", "rec2020-gamma18-chrm.png", "corrupt-iccp.png",
                           "display-p3-large-icc.jpg", "gray-gamma18-icc.png"})
    EXPECT_TRUE(image_file_has_color_tags(kColorTagsData / file)) << file;
  // An sRGB chunk overrides the gAMA beside it.
  EXPECT_FALSE(image_file_has_color_tags(kColorTagsData / "srgb-chunk.png"));
  EXPECT_FALSE(image_file_has_color_tags(kColorTagsData / "no-such-file.png"));
  EXPECT_FALSE(image_file_has_color_tags(kColorTagsData / "srgb-lcms2.icc"));
}

TEST(ImageColorTags, JsonSceneTexturesFollowTheirTags) {
  // Through a loader: the texture is converted, and the scene's warnings say so.
  test::ScratchFolder dir;
  std::filesystem::copy_file(kColorTagsData / "display-p3-icc.png", dir.path() / "p3.png");
  const std::string text = R"({"format": "prism-scene/1", "name": "q", "materials": [
      {"name": "m", "type": "diffuse", "base_color_texture": "p3.png"}],
    "meshes": [{"name": "q", "material": "m", "positions": [[0,0,0], [1,0,0], [0,1,0]],
      "uvs": [[0,0], [1,0], [0,1]], "indices": [0,1,2]}]})";
  const Scene scene = loaders::parse_json_scene(text, (dir.path() / "scene.json").string(), dir.path(), "test", {});
  ASSERT_EQ(scene.textures.size(), 1u);
  expect_row(scene.textures[0], kP3TableToRec709, true, "JSON");
  EXPECT_TRUE(std::any_of(scene.warnings.begin(), scene.warnings.end(),
                          [](const std::string& w) { return w.find("Display P3 (lcms2, tables)") != std::string::npos; }));
}

}  // namespace
}  // namespace prism
