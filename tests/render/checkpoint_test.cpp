// Interrupted renders resume to exactly the uninterrupted image; partial sample ranges
// merge to the image of their union; corrupt checkpoints are refused.
#include "prism/render/checkpoint.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include "prism/core/error.h"
#include "prism/render/aov_images.h"
#include "prism/render/merge_partial_renders.h"
#include "prism/render/renderer.h"
#include "prism/scene/builtin_scenes.h"
#include "support/film_statistics.h"

namespace prism {
namespace {
namespace fs = std::filesystem;

RenderSettings settings_for_test(int spp) {
  RenderSettings s;
  s.width = 40;
  s.height = 32;
  s.samples_per_pixel = spp;
  s.samples_per_pass = 1;  // the tests count passes; pass size does not change the image
  s.seed = 17;
  return s;
}

fs::path temp_file(const std::string& name) {
  return fs::temp_directory_path() / ("prism-checkpoint-test-" + std::to_string(::getpid()) + "-" + name);
}

using test::films_identical;

TEST(Checkpoint, ResumedRenderIsBitwiseIdenticalToUninterrupted) {
  const Scene scene = make_cornell_box();
  const RenderSettings full = settings_for_test(6);
  const RenderResult reference = render(scene, full);

  // Interrupt after 3 passes; the final checkpoint holds exactly those passes.
  std::atomic<bool> cancel{false};
  std::optional<Checkpoint> saved;
  RenderHooks hooks;
  hooks.cancel = &cancel;
  hooks.on_pass = [&](const RenderProgress& p) { cancel = p.passes_done == 3; };
  hooks.on_checkpoint = [&](const Film& film, int next) {
    saved = Checkpoint{image_fingerprint(scene, full), 0, next, film};
  };
  RenderSettings two_threads = full;
  two_threads.threads = 2;
  const RenderResult interrupted = render(scene, two_threads, hooks);
  ASSERT_EQ(interrupted.stop_reason, StopReason::cancelled);
  ASSERT_TRUE(saved);
  ASSERT_EQ(saved->next_sample, 3);

  const fs::path path = temp_file("resume.ckp");
  write_checkpoint(path, *saved);
  const Checkpoint loaded = read_checkpoint(path);
  fs::remove(path);
  EXPECT_EQ(loaded.fingerprint, image_fingerprint(scene, full));
  EXPECT_TRUE(films_identical(loaded.film, saved->film));

  RenderSettings one_thread = full;
  one_thread.threads = 1;
  const ResumeState resume{loaded.film, loaded.next_sample};
  const RenderResult resumed = render(scene, one_thread, RenderHooks{}, &resume);
  EXPECT_EQ(resumed.passes_done, 6);
  EXPECT_TRUE(films_identical(resumed.film, reference.film)) << "resumed film differs from the uninterrupted one";
}

TEST(Checkpoint, PeriodicCheckpointsAreWritten) {
  const Scene scene = make_cornell_box();
  int calls = 0, last_next = 0;
  RenderHooks hooks;
  hooks.checkpoint_interval_seconds = 1e-9;  // after every pass
  hooks.on_checkpoint = [&](const Film&, int next) {
    ++calls;
    last_next = next;
  };
  render(scene, settings_for_test(4), hooks);
  EXPECT_EQ(calls, 4);  // three during the render, one at the end
  EXPECT_EQ(last_next, 4);
}

TEST(Checkpoint, CorruptTruncatedAndForeignFilesAreRefused) {
  const Scene scene = make_cornell_box();
  const RenderResult r = render(scene, settings_for_test(1));
  const fs::path path = temp_file("corrupt.ckp");
  write_checkpoint(path, Checkpoint{1, 0, 1, r.film});
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const auto write_bytes = [&](const std::string& b) { std::ofstream(path, std::ios::binary) << b; };

  std::string flipped = bytes;
  flipped[bytes.size() / 2] ^= 0x40;
  write_bytes(flipped);
  EXPECT_THROW(read_checkpoint(path), IoError);
  write_bytes(bytes.substr(0, bytes.size() - 100));
  EXPECT_THROW(read_checkpoint(path), IoError);
  write_bytes("not a checkpoint at all, just text");
  EXPECT_THROW(read_checkpoint(path), IoError);
  std::string huge = bytes;
  huge[20] = '\x7f';  // width field: absurd size must fail before allocating
  huge[21] = huge[22] = huge[23] = '\x7f';
  write_bytes(huge);
  EXPECT_THROW(read_checkpoint(path), IoError);
  fs::remove(path);
  EXPECT_THROW(read_checkpoint(path), IoError);
}

bool aovs_identical(const Film& a, const Film& b) {
  const FilmAovSums &x = a.aov_sums(), &y = b.aov_sums();
  return x.set == y.set && x.albedo == y.albedo && x.normal == y.normal && x.depth == y.depth &&
         x.depth_hits == y.depth_hits && x.cross == y.cross;
}

TEST(Checkpoint, AovsRoundTripAndResumeBitwiseIdentically) {
  const Scene scene = make_cornell_box();
  RenderSettings full = settings_for_test(5);
  full.aovs = AovSet{true, true, true, true};
  const RenderResult reference = render(scene, full);
  for (const AovSet set : {AovSet{true, true, true, true}, AovSet{false, true, false}, AovSet{true, false, true},
                           AovSet{false, false, false, true}}) {
    RenderSettings s = full;
    s.aovs = set;
    std::atomic<bool> cancel{false};
    std::optional<Checkpoint> saved;
    RenderHooks hooks;
    hooks.cancel = &cancel;
    hooks.on_pass = [&](const RenderProgress& p) { cancel = p.passes_done == 2; };
    hooks.on_checkpoint = [&](const Film& film, int next) { saved = Checkpoint{7, 0, next, film}; };
    render(scene, s, hooks);
    ASSERT_TRUE(saved);
    const fs::path path = temp_file("aov.ckp");
    write_checkpoint(path, *saved);
    const Checkpoint loaded = read_checkpoint(path);
    fs::remove(path);
    EXPECT_EQ(loaded.film.aovs(), set);
    EXPECT_TRUE(films_identical(loaded.film, saved->film) && aovs_identical(loaded.film, saved->film));

    const ResumeState resume{loaded.film, loaded.next_sample};
    const RenderResult resumed = render(scene, s, RenderHooks{}, &resume);
    const RenderResult uninterrupted = set == full.aovs ? reference : render(scene, s);
    EXPECT_TRUE(films_identical(resumed.film, uninterrupted.film));
    EXPECT_TRUE(aovs_identical(resumed.film, uninterrupted.film)) << "resumed AOVs differ (set " << set.bits() << ")";
    // A checkpoint resumes only into a render that keeps the same AOVs.
    RenderSettings other = s;
    other.aovs.normal = !other.aovs.normal;
    EXPECT_THROW(render(scene, other, RenderHooks{}, &resume), UsageError);
  }
}

TEST(Checkpoint, OldFormatVersionIsRefusedWithAClearMessage) {
  const Scene scene = make_cornell_box();
  const RenderResult r = render(scene, settings_for_test(1));
  const fs::path path = temp_file("v1.ckp");
  write_checkpoint(path, Checkpoint{1, 0, 1, r.film});
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  bytes[8] = 1;  // the u32 version after the magic, as version 1 wrote it
  bytes[9] = bytes[10] = bytes[11] = 0;
  std::ofstream(path, std::ios::binary) << bytes;
  try {
    read_checkpoint(path);
    ADD_FAILURE() << "a version-1 checkpoint was accepted";
  } catch (const IoError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("version 1 is not supported"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << "not one line: " << what;
  }
  fs::remove(path);
}

TEST(Fingerprint, CoversWhatChangesPixelsOnly) {
  const Scene scene = make_cornell_box();
  const RenderSettings base = settings_for_test(8);
  RenderSettings other = base;
  other.samples_per_pixel = 100;
  other.threads = 1;
  other.time_limit_seconds = 5;
  EXPECT_EQ(image_fingerprint(scene, base), image_fingerprint(scene, other));
  other = base;
  other.seed = 18;
  EXPECT_NE(image_fingerprint(scene, base), image_fingerprint(scene, other));
  other = base;
  other.path.max_depth = 3;
  EXPECT_NE(image_fingerprint(scene, base), image_fingerprint(scene, other));
  Scene moved = scene;
  moved.camera.eye.x += 1.0f;
  EXPECT_NE(image_fingerprint(scene, base), image_fingerprint(moved, base));
  // A normal map changes the image, and so does its scale.
  Scene mapped = scene;
  mapped.textures.push_back(TextureImage{"bumps", 1, 1, 3, {0.6f, 0.5f, 0.9f}, {}});
  mapped.materials[0].normal_texture = 0;
  EXPECT_NE(image_fingerprint(scene, base), image_fingerprint(mapped, base));
  Scene rescaled = mapped;
  rescaled.materials[0].normal_scale = 0.5f;
  EXPECT_NE(image_fingerprint(mapped, base), image_fingerprint(rescaled, base));
  Scene bumped = scene;
  bumped.textures.push_back(TextureImage{"heights", 1, 1, 1, {0.5f}, {}});
  bumped.materials[0].bump_texture = 0;
  EXPECT_NE(image_fingerprint(scene, base), image_fingerprint(bumped, base));
}

// Everything else that changes pixels is covered too (renderer.cpp hash_scene_details),
// each only where it is not the default: a checkpoint of one scene never resumes as a
// scene that differs in texels, texture addressing, uvs, instances, glass or lights.
TEST(Fingerprint, CoversTexturesGeometryMaterialsAndLightShapes) {
  const Scene scene = make_cornell_box();
  const RenderSettings base = settings_for_test(8);
  const std::uint64_t reference = image_fingerprint(scene, base);
  // A copy is the same scene.
  EXPECT_EQ(image_fingerprint(Scene(scene), base), reference);
  Scene textured = scene;
  textured.textures.push_back(TextureImage{"albedo", 1, 1, 3, {0.6f, 0.5f, 0.9f}, {}});
  textured.materials[0].base_color_texture = 0;
  const std::uint64_t with_texture = image_fingerprint(textured, base);
  EXPECT_NE(with_texture, reference);
  const auto differs = [&](const char* what, const std::function<void(Scene&)>& change) {
    Scene s = textured;
    change(s);
    EXPECT_NE(image_fingerprint(s, base), with_texture) << what;
  };
  differs("texels", [](Scene& s) { s.textures[0].texels[1] = 0.25f; });
  differs("texture scale", [](Scene& s) { s.textures[0].scale_u = 2.0f; });
  differs("wrap", [](Scene& s) { s.textures[0].wrap_v = TextureWrap::clamp; });
  differs("uvs", [](Scene& s) { s.meshes[0].uvs.assign(s.meshes[0].positions.size(), Vec2f(0.5f, 0.5f)); });
  differs("instances", [](Scene& s) { s.instances.push_back(Instance{0, Transform::translate(Vec3f(1, 0, 0))}); });
  differs("thin glass", [](Scene& s) {
    s.materials[0].type = MaterialType::dielectric;
    s.materials[0].thin_walled = true;
  });
  differs("dispersion", [](Scene& s) {
    s.materials[0].dispersion = DispersionModel::cauchy;
    s.materials[0].dispersion_coefficients = {1.5f, 0.004f};
  });
  differs("opacity", [](Scene& s) { s.materials[0].opacity = 0.5f; });
  differs("conductor", [](Scene& s) {
    s.materials[0].conductor_fresnel = ConductorFresnel::complex_ior;
    s.materials[0].conductor_name = "Au";
  });
  differs("two-sided emission", [](Scene& s) { s.materials[3].emission.two_sided = true; });
}

PartialRender partial(const Scene& scene, int begin, int end) {
  RenderSettings s = settings_for_test(end);
  s.first_sample = begin;
  const RenderResult r = render(scene, s);
  return {"part", ImageRgbF{s.width, s.height, r.film.mean_rgb()}, begin, r.next_sample, "same", {}};
}

TEST(MergePartialRenders, SplitRangesMergeToTheSingleRender) {
  const Scene scene = make_cornell_box();
  const RenderResult whole = render(scene, settings_for_test(8));
  const std::vector<float> expected = whole.film.mean_rgb();
  const MergedRender merged = merge_partial_renders({partial(scene, 4, 8), partial(scene, 0, 3), partial(scene, 3, 4)});
  EXPECT_EQ(merged.samples, 8);
  ASSERT_EQ(merged.ranges.size(), 1u);
  EXPECT_EQ(merged.ranges.front(), std::make_pair(0, 8));
  ASSERT_EQ(merged.image.rgb.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    // Each part's mean was rounded to float once and the weighted sum is formed in
    // double: the merge differs from the direct mean by a few float ulps at most.
    EXPECT_NEAR(merged.image.rgb[i], expected[i], 4e-7f * std::abs(expected[i]) + 1e-30f) << "at " << i;
  }
}

PartialRender partial_with_aovs(const Scene& scene, int begin, int end) {
  RenderSettings s = settings_for_test(end);
  s.first_sample = begin;
  s.aovs = AovSet{true, true, true};
  const RenderResult r = render(scene, s);
  return {"part", ImageRgbF{s.width, s.height, r.film.mean_rgb()}, begin, r.next_sample, "same",
          film_aov_images(r.film, Mat3::identity())};
}

TEST(MergePartialRenders, AovsMergeToTheSingleRendersAovs) {
  Scene scene = make_cornell_box();
  scene.camera.fov_degrees = 60.0f;  // wider than the box: edge pixels are partly covered
  RenderSettings s = settings_for_test(8);
  s.aovs = AovSet{true, true, true};
  const RenderResult whole = render(scene, s);
  const AovImages expected = film_aov_images(whole.film, Mat3::identity());
  const std::vector<PartialRender> parts{partial_with_aovs(scene, 3, 8), partial_with_aovs(scene, 0, 3)};
  const MergedRender merged = merge_partial_renders(parts);
  ASSERT_EQ(merged.aovs.set, s.aovs);
  // As for the beauty: each part's mean was rounded to float once (error ≤ 2⁻²⁴ |part|),
  // the weighted sum is formed in double and rounded once more, and the single render's
  // mean was rounded once too. Normals are signed, so parts can cancel: the bound scales
  // with the largest magnitude involved, not with the result. Depth is weighted by
  // samples × coverage, a float of the part: the same bound.
  const auto near = [&](float got, float want, const std::vector<float> AovImages::*channel, std::size_t i) {
    float scale = std::abs(want);
    for (const auto& p : parts) scale = std::max(scale, std::abs((p.aovs.*channel)[i]));
    return got == want || std::abs(got - want) <= 4e-7f * scale + 1e-30f;
  };
  const auto near_rgb = [&](float got, float want, ImageRgbF AovImages::*layer, std::size_t i) {
    float scale = std::abs(want);
    for (const auto& p : parts) scale = std::max(scale, std::abs((p.aovs.*layer).rgb[i]));
    return got == want || std::abs(got - want) <= 4e-7f * scale + 1e-30f;
  };
  int partly_covered = 0;
  for (std::size_t i = 0; i < expected.depth.size(); ++i) {
    for (std::size_t k = 3 * i; k < 3 * i + 3; ++k) {
      EXPECT_TRUE(near_rgb(merged.aovs.albedo.rgb[k], expected.albedo.rgb[k], &AovImages::albedo, k)) << "albedo " << k;
      EXPECT_TRUE(near_rgb(merged.aovs.normal.rgb[k], expected.normal.rgb[k], &AovImages::normal, k))
          << "normal " << k << ": " << merged.aovs.normal.rgb[k] << " vs " << expected.normal.rgb[k];
    }
    EXPECT_TRUE(near(merged.aovs.depth[i], expected.depth[i], &AovImages::depth, i))
        << "depth at " << i << ": " << merged.aovs.depth[i] << " vs " << expected.depth[i];
    EXPECT_TRUE(near(merged.aovs.depth_coverage[i], expected.depth_coverage[i], &AovImages::depth_coverage, i))
        << "coverage at " << i;
    partly_covered += expected.depth_coverage[i] > 0.0f && expected.depth_coverage[i] < 1.0f;
  }
  EXPECT_GT(partly_covered, 0) << "the test needs pixels whose samples partly miss";
  PartialRender plain = partial(scene, 8, 9);
  EXPECT_THROW(merge_partial_renders({partial_with_aovs(scene, 0, 3), plain}), UsageError);
}

TEST(MergePartialRenders, RejectsIncompatibleParts) {
  const ImageRgbF a{2, 2, std::vector<float>(12, 1.0f)};
  const ImageRgbF b{3, 2, std::vector<float>(18, 1.0f)};
  EXPECT_THROW(merge_partial_renders({}), UsageError);
  EXPECT_THROW(merge_partial_renders({{"a", a, 0, 4, "f", {}}, {"b", b, 4, 8, "f", {}}}), UsageError);
  EXPECT_THROW(merge_partial_renders({{"a", a, 0, 4, "f", {}}, {"b", a, 4, 8, "g", {}}}), UsageError);
  EXPECT_THROW(merge_partial_renders({{"a", a, 0, 4, "f", {}}, {"b", a, 3, 8, "f", {}}}), UsageError);
  EXPECT_THROW(merge_partial_renders({{"a", a, 4, 4, "f", {}}}), UsageError);
  const MergedRender gap = merge_partial_renders({{"a", a, 0, 2, "f", {}}, {"b", a, 5, 8, "f", {}}});
  EXPECT_EQ(gap.ranges.size(), 2u);
  EXPECT_EQ(gap.samples, 5);
}

}  // namespace
}  // namespace prism
