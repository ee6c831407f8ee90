// OpenEXR colour textures in other primaries than Rec.709: the `chromaticities` attribute
// says which (ACEScg textures are common in ACES pipelines), and Prism's textures are
// Rec.709, so a colour texture's texels are converted at load (Bradford between whites)
// and data textures (normal, roughness maps) are read as stored. Before, every EXR texel
// was read as Rec.709 whatever its file said.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/color_space.h"
#include "prism/io/exr.h"
#include "prism/io/png.h"
#include "prism/scene/loaders/json_scene.h"
#include "prism/scene/loaders/pbrt_scene.h"
#include "prism/scene/loaders/texture_png.h"
#include "prism/scene/scene_summary.h"
#include "prism/scene/texture_file.h"
#include "scene/loaders/loader_test_files.h"
#include "support/scratch_folder.h"

namespace prism {
namespace {

ExrChromaticities exr_chromaticities_of(const char* name) {
  const color::ColorSpace& s = color::color_space(name);
  const auto f = [](double v) { return static_cast<float>(v); };
  return {f(s.red.x), f(s.red.y), f(s.green.x), f(s.green.y), f(s.blue.x), f(s.blue.y), f(s.white.x), f(s.white.y)};
}

// Two texels in gamut for Rec.709 and ACEScg's pure green, which is not.
const std::vector<float> kAcescgTexels = {0.5f, 0.25f, 0.125f, 0.2f, 0.4f, 0.3f, 0.0f, 1.0f, 0.0f};

Vec3d acescg_in_rec709(std::size_t texel) {
  const Mat3 m = color::conversion_matrix(color::color_space("acescg"), color::color_space("srgb"));
  return m * Vec3d(kAcescgTexels[3 * texel], kAcescgTexels[3 * texel + 1], kAcescgTexels[3 * texel + 2]);
}

void write_acescg_exr(const std::filesystem::path& path, ExrPixelType type = ExrPixelType::float32) {
  ExrWriteOptions options;
  options.pixel_type = type;
  write_exr(path, ImageRgbF{3, 1, kAcescgTexels}, exr_chromaticities_of("acescg"), {}, options);
}

TEST(ExrTexturePrimaries, ColourTexelsAreConvertedToRec709AndOutOfGamutOnesClipped) {
  test::ScratchFolder dir;
  write_acescg_exr(dir / "acescg.exr");
  const TextureImage colour =
      read_texture_file(dir / "acescg.exr", TextureEncoding::srgb, TextureLimits(4096), TextureContent::color);
  const std::vector<float> texels = colour.linear_values();
  for (std::size_t t = 0; t < 2; ++t)
    for (int k = 0; k < 3; ++k)  // a 3×3 product in double, stored as float
      EXPECT_NEAR(texels[3 * t + k], acescg_in_rec709(t)[k], 1e-6) << t << " " << k;
  // ACEScg green has negative Rec.709 red and blue: clipped to 0, its green kept.
  const Vec3d green = acescg_in_rec709(2);
  ASSERT_LT(green.x, 0.0);
  EXPECT_EQ(texels[6], 0.0f);
  EXPECT_NEAR(texels[7], green.y, 1e-6);
  EXPECT_NE(colour.primaries_note.find("converted to Rec.709"), std::string::npos) << colour.primaries_note;
  EXPECT_NE(colour.primaries_note.find("1 of 3 texels lie outside Rec.709"), std::string::npos)
      << colour.primaries_note;
  // Data is read as stored.
  const TextureImage data =
      read_texture_file(dir / "acescg.exr", TextureEncoding::linear, TextureLimits(4096), TextureContent::data);
  EXPECT_EQ(data.linear_values(), kAcescgTexels);
  EXPECT_TRUE(data.primaries_note.empty());
}

TEST(ExrTexturePrimaries, HalfTexturesStayHalves) {
  test::ScratchFolder dir;
  write_acescg_exr(dir / "half.exr", ExrPixelType::half);
  const TextureImage colour =
      read_texture_file(dir / "half.exr", TextureEncoding::srgb, TextureLimits(4096), TextureContent::color);
  ASSERT_TRUE(colour.has_halves());
  const std::vector<float> texels = colour.linear_values();
  // Halves hold 11 significant bits: 2⁻¹¹ relative, once on reading and once on storing.
  for (std::size_t t = 0; t < 2; ++t)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(texels[3 * t + k], acescg_in_rec709(t)[k], 1e-3 * acescg_in_rec709(t)[k]);
}

TEST(ExrTexturePrimaries, Rec709AndUnlabelledFilesAreReadAsStored) {
  test::ScratchFolder dir;
  write_exr(dir / "rec709.exr", ImageRgbF{3, 1, kAcescgTexels}, exr_chromaticities_of("srgb"));
  const TextureImage t =
      read_texture_file(dir / "rec709.exr", TextureEncoding::srgb, TextureLimits(4096), TextureContent::color);
  EXPECT_EQ(t.linear_values(), kAcescgTexels);
  EXPECT_TRUE(t.primaries_note.empty());
}

TEST(ExrTexturePrimaries, LoadersConvertColourTexturesAndSaySo) {
  test::ScratchFolder dir;
  write_acescg_exr(dir / "albedo.exr");
  // JSON: the base colour texture is colour even when given as linear; the bump map, the
  // same file, is data.
  const std::string json = R"({"format": "prism-scene/1", "name": "q",
    "materials": [{"name": "m", "type": "diffuse", "base_color_texture": {"file": "albedo.exr", "encoding": "linear"},
                   "bump_texture": "albedo.exr"}],
    "meshes": [{"name": "q", "material": "m", "positions": [[0,0,0], [1,0,0], [0,1,0]], "uvs": [[0,0], [1,0], [0,1]],
                "indices": [0,1,2]}]})";
  const Scene scene = loaders::parse_json_scene(json, "scene.json", dir.path(), "q");
  const Material& m = scene.materials[0];
  EXPECT_NEAR(scene.textures[static_cast<std::size_t>(m.base_color_texture)].linear_values()[0], acescg_in_rec709(0).x,
              1e-6);
  EXPECT_EQ(scene.textures[static_cast<std::size_t>(m.bump_texture)].linear_values(), kAcescgTexels);
  bool warned = false;
  for (const std::string& w : scene.warnings) warned |= w.find("converted to Rec.709") != std::string::npos;
  EXPECT_TRUE(warned);
  // pbrt-v4: a "spectrum" imagemap is colour whatever its encoding, a "float" one data, and
  // keeps its file's colour space (pbrt-v4's image textures do): ACEScg texels as written,
  // on a material whose base colour is ACEScg.
  const std::string pbrt = "WorldBegin\n"
                           "Texture \"c\" \"spectrum\" \"imagemap\" \"string filename\" \"albedo.exr\" "
                           "\"string encoding\" \"linear\"\n"
                           "Material \"diffuse\" \"texture reflectance\" \"c\"\n"
                           "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 2] "
                           "\"point2 uv\" [0 0 1 0 0 1]\n";
  const Scene p = loaders::parse_pbrt_scene(pbrt, "scene.pbrt", dir.path());
  const Material& pm = p.materials[p.meshes[0].material];
  ASSERT_GE(pm.base_color_texture, 0);
  const TextureImage& pt = p.textures[static_cast<std::size_t>(pm.base_color_texture)];
  EXPECT_EQ(pt.texel_space, ColorPickerSpace::acescg);
  EXPECT_EQ(pt.linear_values(), kAcescgTexels);
  EXPECT_EQ(pm.base_color_space, ColorPickerSpace::acescg);
  EXPECT_EQ(pm.base_color, Vec3f(1.0f));
}

// pbrt-v4 image textures in other primaries: a Rec.2020 one is kept in Rec.2020 (and its
// material's base colour is Rec.2020), an ACES2065-1 one goes to ACEScg (AP0 is imaginary),
// a Rec.709 one stays as it was, on an sRGB material; a uv-transformed copy keeps its
// texture's space.
TEST(ExrTexturePrimaries, PbrtImageTexturesKeepTheirFilesColourSpace) {
  test::ScratchFolder dir;
  for (const char* space : {"rec2020", "aces2065-1", "srgb"})
    write_exr(dir / (std::string(space) + ".exr"), ImageRgbF{3, 1, kAcescgTexels}, exr_chromaticities_of(space));
  const std::string pbrt =
      "WorldBegin\n"
      "Texture \"a\" \"spectrum\" \"imagemap\" \"string filename\" \"rec2020.exr\"\n"
      "Texture \"b\" \"spectrum\" \"imagemap\" \"string filename\" \"aces2065-1.exr\"\n"
      "Texture \"c\" \"spectrum\" \"imagemap\" \"string filename\" \"srgb.exr\"\n"
      "Texture \"d\" \"spectrum\" \"imagemap\" \"string filename\" \"rec2020.exr\" \"float uscale\" 2\n";
  std::string shapes;
  for (const char* t : {"a", "b", "c", "d"})
    shapes += std::string("AttributeBegin\nMaterial \"diffuse\" \"texture reflectance\" \"") + t +
              "\"\nShape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 2] "
              "\"point2 uv\" [0 0 1 0 0 1]\nAttributeEnd\n";
  const Scene scene = loaders::parse_pbrt_scene(pbrt + shapes, "scene.pbrt", dir.path());
  ASSERT_EQ(scene.meshes.size(), 4u);
  const ColorPickerSpace expected[] = {ColorPickerSpace::rec2020, ColorPickerSpace::acescg, ColorPickerSpace::srgb,
                                       ColorPickerSpace::rec2020};
  for (std::size_t i = 0; i < 4; ++i) {
    const Material& m = scene.materials[scene.meshes[i].material];
    ASSERT_GE(m.base_color_texture, 0) << i;
    EXPECT_EQ(scene.textures[static_cast<std::size_t>(m.base_color_texture)].texel_space, expected[i]) << i;
    EXPECT_EQ(m.base_color_space, expected[i]) << i;
  }
  // Rec.2020 texels as written; AP0 ones converted to AP1.
  const auto texels_of = [&](std::size_t mesh) {
    return scene.textures[static_cast<std::size_t>(scene.materials[scene.meshes[mesh].material].base_color_texture)]
        .linear_values();
  };
  EXPECT_EQ(texels_of(0), kAcescgTexels);
  EXPECT_EQ(texels_of(2), kAcescgTexels);
  const Mat3 ap0_to_ap1 = color::conversion_matrix(color::color_space("aces2065-1"), color::color_space("acescg"));
  EXPECT_NEAR(texels_of(1)[0], (ap0_to_ap1 * Vec3d(0.5, 0.25, 0.125)).x, 1e-6);
}

// A wide-gamut material's base colour asks for its own space: an ACEScg file read into
// ACEScg is stored as written (no conversion, no note), into Rec.2020 converted, where
// ACEScg's pure green, outside Rec.2020 too, is clipped and noted; a Rec.709 file goes into
// the wide space losing nothing, without a note.
TEST(ExrTexturePrimaries, WideGamutContentKeepsWhatRec709CannotHold) {
  test::ScratchFolder dir;
  write_acescg_exr(dir / "acescg.exr");
  const TextureImage same =
      read_texture_file(dir / "acescg.exr", TextureEncoding::srgb, TextureLimits(4096), TextureContent::color_acescg);
  EXPECT_EQ(same.texel_space, ColorPickerSpace::acescg);
  EXPECT_EQ(same.linear_values(), kAcescgTexels);
  EXPECT_TRUE(same.primaries_note.empty()) << same.primaries_note;

  const TextureImage wide =
      read_texture_file(dir / "acescg.exr", TextureEncoding::srgb, TextureLimits(4096), TextureContent::color_rec2020);
  EXPECT_EQ(wide.texel_space, ColorPickerSpace::rec2020);
  const Mat3 to_rec2020 = color::conversion_matrix(color::color_space("acescg"), color::color_space("rec2020"));
  const std::vector<float> texels = wide.linear_values();
  for (std::size_t t = 0; t < 2; ++t) {
    const Vec3d expected =
        to_rec2020 * Vec3d(kAcescgTexels[3 * t], kAcescgTexels[3 * t + 1], kAcescgTexels[3 * t + 2]);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(texels[3 * t + k], expected[k], 1e-6) << t << " " << k;
  }
  ASSERT_LT(min_component(to_rec2020 * Vec3d(0, 1, 0)), 0.0);  // AP1's green lies outside Rec.2020
  EXPECT_GE(min_component(Vec3f(texels[6], texels[7], texels[8])), 0.0f);
  EXPECT_NE(wide.primaries_note.find("1 of 3 texels lie outside Rec.2020"), std::string::npos) << wide.primaries_note;

  write_exr(dir / "plain.exr", ImageRgbF{3, 1, kAcescgTexels}, exr_chromaticities_of("srgb"));
  const TextureImage plain =
      read_texture_file(dir / "plain.exr", TextureEncoding::srgb, TextureLimits(4096), TextureContent::color_acescg);
  EXPECT_EQ(plain.texel_space, ColorPickerSpace::acescg);
  const Mat3 to_acescg = color::conversion_matrix(color::color_space("srgb"), color::color_space("acescg"));
  EXPECT_NEAR(plain.linear_values()[0], (to_acescg * Vec3d(0.5, 0.25, 0.125)).x, 1e-6);
  EXPECT_TRUE(plain.primaries_note.empty()) << plain.primaries_note;
}

// The JSON loader asks for the material's space: the same ACEScg file is the ACEScg texels
// as written on an ACEScg material and clipped Rec.709 ones on an sRGB material (two
// entries), while a PNG, which has no primaries here, is one entry for both.
TEST(ExrTexturePrimaries, JsonWideGamutMaterialReadsItsOpenExrInItsSpace) {
  test::ScratchFolder dir;
  write_acescg_exr(dir / "albedo.exr");
  write_png(dir / "albedo.png", EncodedImage{2, 2, 3, 8, std::vector<std::uint16_t>(12, 128)});
  const std::string json = R"({"format": "prism-scene/1", "name": "q",
    "materials": [{"name": "wide", "type": "diffuse", "base_color_space": "acescg", "base_color_texture": "albedo.exr"},
                  {"name": "narrow", "type": "diffuse", "base_color_texture": "albedo.exr"},
                  {"name": "wide-png", "type": "diffuse", "base_color_space": "acescg", "base_color_texture": "albedo.png"},
                  {"name": "narrow-png", "type": "diffuse", "base_color_texture": "albedo.png"}],
    "meshes": [{"name": "q", "material": "wide", "positions": [[0,0,0], [1,0,0], [0,1,0]], "uvs": [[0,0], [1,0], [0,1]],
                "indices": [0,1,2]}]})";
  const Scene scene = loaders::parse_json_scene(json, "scene.json", dir.path(), "q");
  const TextureImage& wide = scene.textures[static_cast<std::size_t>(scene.materials[0].base_color_texture)];
  const TextureImage& narrow = scene.textures[static_cast<std::size_t>(scene.materials[1].base_color_texture)];
  EXPECT_EQ(wide.texel_space, ColorPickerSpace::acescg);
  EXPECT_EQ(wide.linear_values(), kAcescgTexels);
  EXPECT_EQ(narrow.texel_space, ColorPickerSpace::srgb);
  EXPECT_EQ(narrow.linear_values()[6], 0.0f);  // the green's clipped red
  EXPECT_EQ(scene.materials[2].base_color_texture, scene.materials[3].base_color_texture);
  EXPECT_EQ(scene.textures[static_cast<std::size_t>(scene.materials[2].base_color_texture)].texel_space,
            ColorPickerSpace::srgb);
  // `prism info` says which texture is held in ACEScg, and only that one.
  const std::string summary = format_scene_summary(scene);
  EXPECT_NE(summary.find("albedo.exr 3x1x3 float ACEScg"), std::string::npos) << summary;
  EXPECT_NE(summary.find("albedo.exr 3x1x3 float 0"), std::string::npos) << summary;
  EXPECT_EQ(summary.find("sRGB Rec.709"), std::string::npos) << summary;  // the PNG's line says none
}

// The scene writers' PNGs are read back as Rec.709: a texture held in ACEScg goes back to
// Rec.709 there (what lies outside it clipped, like values above 1), not as its ACEScg
// numbers.
TEST(ExrTexturePrimaries, WritersPngsHoldRec709) {
  test::ScratchFolder dir;
  write_acescg_exr(dir / "acescg.exr");
  const TextureImage wide =
      read_texture_file(dir / "acescg.exr", TextureEncoding::srgb, TextureLimits(4096), TextureContent::color_acescg);
  const std::vector<unsigned char> png = loaders::encode_texture_png(wide, TextureEncoding::srgb);
  const TextureImage back = decode_texture_memory(png, "back.png", TextureEncoding::srgb, TextureLimits(4096), TextureContent::color);
  EXPECT_EQ(back.texel_space, ColorPickerSpace::srgb);
  const std::vector<float> texels = back.linear_values();
  for (std::size_t t = 0; t < 3; ++t) {
    const Vec3d expected = min(max(acescg_in_rec709(t), Vec3d(0.0)), Vec3d(1.0));
    // 8-bit sRGB codes: half a code step, at most 0.5/255 × the OETF's slope at the value
    // (12.92 near 0) in linear terms, within 0.03 here.
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(texels[3 * t + k], expected[k], 0.03 * std::max(expected[k], 0.1)) << t << k;
  }
}

}  // namespace
}  // namespace prism
