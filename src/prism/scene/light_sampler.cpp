#include "prism/scene/light_sampler.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>

#include "prism/core/branch_free.h"
#include "prism/core/frame.h"
#include "prism/core/mat3.h"
#include "prism/core/parallel.h"
#include "prism/color/color_space.h"
#include "prism/sampling/warps.h"
#include "prism/scene/emission.h"
#include "prism/scene/environment_lookup.h"
#include "prism/scene/environment_mapping.h"
#include "prism/scene/texture_sampling.h"

namespace prism {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

float radians(float degrees) { return degrees * kPi / 180.0f; }

// Smooth spot falloff between the outer and inner cone (a Hermite smoothstep in cos θ,
// as glTF's KHR_lights_punctual recommends a smooth transition).
float spot_falloff(float cos_theta, float cos_outer, float cos_inner) {
  if (cos_theta >= cos_inner) return 1.0f;
  if (cos_theta <= cos_outer) return 0.0f;
  const float t = (cos_theta - cos_outer) / (cos_inner - cos_outer);
  return t * t * (3.0f - 2.0f * t);
}

// World → map for the environment: the inverse of map → world's linear part (loaders may
// give scales or mirrors as well as rotations; directions are normalised after it).
// A singular matrix cannot orient a map: the identity stands in (loaders refuse those).
Transform inverse_linear(const Transform& t) {
  Mat3 a;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a.m[i][j] = t.m[i][j];
  Transform r;
  if (determinant(a) == 0.0) return r;
  const Mat3 inv = inverse(a);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = static_cast<float>(inv.m[i][j]);
  return r;
}

Vec2f barycentric_uv(Vec2f uv0, Vec2f duv1, Vec2f duv2, Vec2f b) {
  return {uv0.x + duv1.x * b.x + duv2.x * b.y, uv0.y + duv1.y * b.x + duv2.y * b.y};
}

// Y(colour ⊙ texel) / Y(colour) of an emission texture, with the picker space's luminance
// row looked up once per emissive mesh (these run per texel and per quadrature point); a
// texel in another space than the colour's is converted to it first (scene/emission.h).
struct TexelEmissionWeight {
  TexelEmissionWeight(const TextureImage& texture_, const Emission& emission)
      : texture(texture_),
        colour(emission.color),
        luminance_row(picker_color_space(emission.color_space).rgb_to_xyz.row(1)),
        y_colour(dot(luminance_row, Vec3d(emission.color))),
        converts(texture_.texel_space != emission.color_space),
        to_picker(picker_space_conversion(texture_.texel_space, emission.color_space)) {}

  // At uv, bilinear on the finest level.
  double operator()(Vec2f uv) const {
    if (!(y_colour > 0.0)) return 0.0;
    const TexelRgba t = sample_bilinear(texture, apply_uv_transform(texture, uv));
    return of_rgb(Vec3f(t[0], t[1], t[2]));  // greys come expanded to (g, g, g) (texture_sampling.h)
  }
  // Of texel (x, y) itself.
  double at_texel(int x, int y) const { return y_colour > 0.0 ? of_rgb(texel_rgb(texture, x, y)) : 0.0; }
  double of_rgb(const Vec3f& rgb) const {
    if (converts) return std::max(0.0, dot(luminance_row, Vec3d(colour) * (to_picker * Vec3d(rgb))) / y_colour);
    return std::max(0.0, dot(luminance_row, Vec3d(colour * rgb)) / y_colour);
  }

  const TextureImage& texture;
  Vec3f colour;
  Vec3d luminance_row;
  double y_colour;
  bool converts;  // texels are in another space than the colour
  Mat3 to_picker;
};

// The terms of of_rgb's dot product for an 8-bit texture, per channel and code:
// luminance_row[k] · (colour[k] ⊙ value(code)), the float product widened as Vec3d does,
// so that (term_0 + term_1) + term_2 is the dot product's own sum, bit for bit. Three
// loads per texel instead of decoding it through texel_rgb's checks of the storage.
struct CodedEmissionTerms {
  std::array<std::array<double, 256>, 3> term{};
  explicit CodedEmissionTerms(const TexelEmissionWeight& weight) {
    const std::array<float, 256>& values = code_values(weight.texture.encoding);
    for (std::size_t k = 0; k < 3; ++k)
      for (std::size_t code = 0; code < 256; ++code)
        term[k][code] = weight.luminance_row[k] * double(weight.colour[k] * values[code]);
  }
  // TexelEmissionWeight::at_texel of texel (x, y) (y_colour > 0).
  double at(const TextureImage& texture, int x, int y, double y_colour) const {
    const std::uint8_t* p =
        &texture.codes[(static_cast<std::size_t>(y) * texture.width + x) * static_cast<std::size_t>(texture.channels)];
    const bool colour = texture.channels >= 3;
    const std::uint8_t r = p[0], g = colour ? p[1] : r, b = colour ? p[2] : r;
    return std::max(0.0, term[0][r] + term[1][g] + term[2][b]) / y_colour;
  }
};

// The texture's mean weight over its texels (once per emissive mesh): rows summed in
// parallel, then added in row order, so the result does not depend on the thread count.
double texture_mean_weight(const TexelEmissionWeight& weight) {
  const TextureImage& texture = weight.texture;
  std::vector<double> row_sums(static_cast<std::size_t>(std::max(0, texture.height)), 0.0);
  const auto sum_rows = [&](const auto& texel_weight) {
    parallel_for(row_sums.size(), 16, [&](std::size_t begin, std::size_t end) {
      for (std::size_t y = begin; y < end; ++y)
        for (int x = 0; x < texture.width; ++x) row_sums[y] += texel_weight(x, static_cast<int>(y));
    });
  };
  if (texture.has_codes() && weight.y_colour > 0.0 && !weight.converts) {
    const CodedEmissionTerms terms(weight);  // 8-bit textures: their codes' terms, tabulated
    sum_rows([&](int x, int y) { return terms.at(texture, x, y, weight.y_colour); });
  } else {
    sum_rows([&](int x, int y) { return weight.at_texel(x, y); });
  }
  double sum = 0.0;
  for (const double s : row_sums) sum += s;
  return sum / std::max(1, texture.width * texture.height);
}

// Relative power of a textured emissive triangle: the mean over its uv footprint of
// Y(colour ⊙ texel) / Y(colour), by 16 stratified points, plus a floor of 1% of the
// texture's mean (see the header).
double textured_triangle_weight(const TexelEmissionWeight& weight, double texture_mean, Vec2f uv0, Vec2f duv1,
                                Vec2f duv2) {
  constexpr int kGrid = 4;
  double sum = 0.0;
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j) {
      const Vec2f b = sample_uniform_triangle(Vec2f((i + 0.5f) / kGrid, (j + 0.5f) / kGrid));
      sum += weight(barycentric_uv(uv0, duv1, duv2, b));
    }
  return sum / (kGrid * kGrid) + 0.01 * texture_mean;
}

}  // namespace

LightSampler::LightSampler(const Scene& scene, const Bounds3f& world, const LightSamplerOptions& options)
    : options_(options) {
  first_triangle_of_mesh_.assign(scene.meshes.size(), -1);
  std::vector<double> power;
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const TriangleMesh& mesh = scene.meshes[m];
    const Material& material = scene.materials[mesh.material];
    if (!material.is_emissive()) continue;
    first_triangle_of_mesh_[m] = static_cast<std::int64_t>(emitters_.size());
    const int tex = material.emission.texture;
    const bool textured = tex >= 0 && static_cast<std::size_t>(tex) < scene.textures.size() && !mesh.uvs.empty();
    std::optional<TexelEmissionWeight> texel_weight;
    if (textured) texel_weight.emplace(scene.textures[static_cast<std::size_t>(tex)], material.emission);
    const double texture_mean = textured ? texture_mean_weight(*texel_weight) : 0.0;
    // Each textured triangle's quadrature is its own: computed in parallel up front.
    std::vector<double> texture_weights;
    if (textured) {
      texture_weights.resize(mesh.triangle_count());
      parallel_for(mesh.triangle_count(), 256, [&](std::size_t begin, std::size_t end) {
        for (std::size_t t = begin; t < end; ++t) {
          const Vec2f& uv0 = mesh.uvs[mesh.indices[3 * t + 0]];
          const Vec2f& uv1 = mesh.uvs[mesh.indices[3 * t + 1]];
          const Vec2f& uv2 = mesh.uvs[mesh.indices[3 * t + 2]];
          texture_weights[t] = textured_triangle_weight(*texel_weight, texture_mean, uv0,
                                                        Vec2f(uv1.x - uv0.x, uv1.y - uv0.y),
                                                        Vec2f(uv2.x - uv0.x, uv2.y - uv0.y));
        }
      });
    }
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
      const Vec3f& p0 = mesh.positions[mesh.indices[3 * t + 0]];
      const Vec3f& p1 = mesh.positions[mesh.indices[3 * t + 1]];
      const Vec3f& p2 = mesh.positions[mesh.indices[3 * t + 2]];
      const Vec3f n = cross(p1 - p0, p2 - p0);
      const float twice_area = length(n);
      Emitter e{};
      e.kind = Kind::triangle;
      e.emitter = mesh.material;
      e.triangle.p0 = p0;
      e.triangle.e1 = p1 - p0;
      e.triangle.e2 = p2 - p0;
      e.triangle.normal = twice_area > 0.0f ? n / twice_area : Vec3f(0.0f);
      e.triangle.area = 0.5f * twice_area;
      e.triangle.two_sided = material.emission.two_sided;
      e.textured = textured;
      double texture_weight = 1.0;
      if (e.textured) {
        e.uv0 = mesh.uvs[mesh.indices[3 * t + 0]];
        const Vec2f& uv1 = mesh.uvs[mesh.indices[3 * t + 1]];
        const Vec2f& uv2 = mesh.uvs[mesh.indices[3 * t + 2]];
        e.duv1 = Vec2f(uv1.x - e.uv0.x, uv1.y - e.uv0.y);
        e.duv2 = Vec2f(uv2.x - e.uv0.x, uv2.y - e.uv0.y);
        texture_weight = texture_weights[t];
      }
      emitters_.push_back(e);
      // Lambertian emitter: Φ = π · L · A per emitting side. Zero-area triangles get
      // zero power and are never chosen.
      power.push_back(kPi * double(material.emission.luminance_nits) * e.triangle.area *
                      (e.triangle.two_sided ? 2.0 : 1.0) *
                      texture_weight);
    }
  }
  const Vec3f diagonal = world.empty() ? Vec3f(1.0f) : world.diagonal();
  const float world_radius = 0.5f * length(diagonal);
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    const Light& light = scene.lights[l];
    Emitter e{};
    e.emitter = static_cast<std::uint32_t>(scene.materials.size() + l);
    e.position = light.position;
    const float len = length(light.direction);
    e.axis = len > 0.0f ? light.direction / len : Vec3f(0.0f, -1.0f, 0.0f);
    const double intensity = std::max(0.0f, light.intensity);
    switch (light.type) {
      case LightType::point:
        e.kind = Kind::point;
        power.push_back(4.0 * kPi * intensity);  // Φ = 4π I
        break;
      case LightType::spot: {
        e.kind = Kind::spot;
        e.cos_inner = std::cos(radians(light.spot_inner_angle_degrees));
        e.cos_outer = std::cos(radians(std::max(light.spot_outer_angle_degrees, light.spot_inner_angle_degrees)));
        // Φ ≈ 2π I (1 − cos θ_mid): the cone half-way through the falloff.
        const double cos_mid = 0.5 * (double(e.cos_inner) + e.cos_outer);
        power.push_back(2.0 * kPi * intensity * (1.0 - cos_mid));
        break;
      }
      case LightType::directional: {
        e.kind = Kind::directional;
        const float half_angle = 0.5f * radians(std::clamp(light.angular_diameter_degrees, 0.0f, 180.0f));
        e.cos_max = std::cos(half_angle);
        const float sin2 = 1.0f - e.cos_max * e.cos_max;
        // Illuminance E = ∫_cone L cos θ dω = L π sin²θmax for a disc seen head-on.
        e.disc_radiance_scale = sin2 > 0.0f ? 1.0f / (kPi * sin2) : 1.0f;
        power.push_back(intensity * kPi * double(world_radius) * world_radius);  // E over the scene's disc
        break;
      }
      case LightType::environment: {
        if (e.texture || environment_built_) break;  // one environment per scene: the first
        e.kind = Kind::environment;
        e.intensity_nits = static_cast<float>(intensity);
        e.mapping = light.environment_mapping;
        e.map_to_world = light.environment_to_world;
        e.world_to_map = inverse_linear(light.environment_to_world);
        e.texture = environment_map(scene);  // this is the first environment light: its map
        const double average_luminance = build_environment_distribution(e);
        environment_built_ = true;
        // Φ ≈ π R² · π L̄: the scene's disc lit by the sky's average luminance.
        power.push_back(kPi * double(world_radius) * world_radius * kPi * intensity * average_luminance);
        break;
      }
    }
    if (light.type == LightType::environment && e.kind != Kind::environment) continue;
    emitters_.push_back(e);
  }

  double total = 0.0;
  for (double p : power) total += p;
  if (!(total > 0.0)) {
    emitters_.clear();
    first_triangle_of_mesh_.assign(scene.meshes.size(), -1);
    return;
  }
  double running = 0.0;
  for (double p : power) {
    running += p;
    selection_pmf_.push_back(static_cast<float>(p / total));
    selection_cdf_.push_back(static_cast<float>(running / total));
  }
  selection_cdf_.back() = 1.0f;
  uses_selection_number_ = !options_.reuse_selection_sample ||
                           std::any_of(selection_pmf_.begin(), selection_pmf_.end(),
                                       [](float pmf) { return pmf > 0.0f && pmf < kMinReusedSelectionPmf; });
  for (std::size_t i = 0; i < emitters_.size(); ++i)
    if (emitters_[i].kind == Kind::environment || (emitters_[i].kind == Kind::directional && emitters_[i].cos_max < 1.0f))
      escapable_emitters_.push_back(static_cast<std::uint32_t>(i));
}

// Sampling density ∝ the texel's mean luminance × dω/d(uv) of its centre, so that the
// density over solid angle follows the luminance (pbrt-v4 §12.5.2). The mean is that of the
// bilinearly filtered radiance the estimators read (environment_lookup.h), so the density is
// positive wherever that radiance is. For the equal-area octahedral map the Jacobian is the
// constant 4π and drops out: the distribution is the luminance itself.
double LightSampler::build_environment_distribution(const Emitter& e) {
  if (!e.texture) return 1.0;
  const TextureImage& t = *e.texture;
  // Luminance weights of the space the texels are in (an OpenEXR keeps its own gamut).
  const Vec3d y_row = picker_color_space(t.texel_space).rgb_to_xyz.row(1);
  std::vector<float> luminance(static_cast<std::size_t>(t.width) * t.height);
  for (int y = 0; y < t.height; ++y)
    for (int x = 0; x < t.width; ++x)
      luminance[static_cast<std::size_t>(y) * t.width + x] =
          static_cast<float>(std::max(0.0, dot(y_row, Vec3d(texel_rgb(t, x, y)))));
  double weighted = 0.0, weight = 0.0;
  // Row by row (rows in order, so the sums are those of one pass over the image).
  environment_distribution_ = PiecewiseConstant2D(t.width, t.height, [&](int y, std::span<float> row) {
    // The Jacobian is a function of v alone (environment_mapping.h): once per row, not a
    // sine per texel.
    const double jacobian = environment_solid_angle_per_uv_area(e.mapping, Vec2f(0.5f, (y + 0.5f) / t.height));
    for (int x = 0; x < t.width; ++x) {
      const double lum = environment_texel_mean(luminance, e.mapping, x, y, t.width, t.height);
      row[static_cast<std::size_t>(x)] = static_cast<float>(lum * jacobian);
      weighted += lum * jacobian;
      weight += jacobian;
    }
  });
  return weight > 0.0 ? weighted / weight : 0.0;
}

Vec3f LightSampler::environment_rgb_at(const Emitter& e, Vec2f uv) {
  return environment_radiance_bilinear(*e.texture, e.mapping, uv) * e.intensity_nits;
}

float LightSampler::environment_pdf_at(EnvironmentMapping mapping, Vec2f uv) const {
  const float jacobian = environment_solid_angle_per_uv_area(mapping, uv);
  if (!(jacobian > 0.0f)) return 0.0f;
  return environment_distribution_.pdf(uv) / jacobian;
}

Vec3f LightSampler::map_direction(const Emitter& e, const Vec3f& world_direction) {
  return normalize(e.world_to_map.apply_vector(world_direction));
}

std::optional<LightSample> LightSampler::sample(const Vec3f& reference, float u_select, Vec2f u_point,
                                                const Vec3f& receiver_normal) const {
  const std::optional<Selection> chosen = select(u_select, u_point);
  if (!chosen) return std::nullopt;
  return sample_selected(*chosen, reference, receiver_normal);
}

std::optional<LightSample> LightSampler::sample_selected(const Selection& chosen, const Vec3f& reference,
                                                         const Vec3f& receiver_normal) const {
  // One LightSample object from here to the caller: returned as a prvalue here and as
  // the single named result in sample_emitter (copy elision), not copied at each level.
  return sample_emitter(chosen.emitter_index, reference, chosen.u_point, receiver_normal, chosen.pmf);
}

std::optional<LightSample> LightSampler::sample_emitter(std::size_t index, const Vec3f& reference, Vec2f u,
                                                        const Vec3f& receiver_normal, float selection_pmf) const {
  std::optional<LightSample> result(std::in_place);
  if (fill_emitter_sample(index, reference, u, receiver_normal, *result))
    result->pdf *= selection_pmf;
  else
    result.reset();
  return result;
}

bool LightSampler::fill_emitter_sample(std::size_t index, const Vec3f& reference, Vec2f u,
                                       const Vec3f& receiver_normal, LightSample& s) const {
  const Emitter& e = emitters_[index];
  s.emitter = e.emitter;
  switch (e.kind) {
    case Kind::triangle: {
      const auto t = options_.triangle == TriangleLightSampling::area
                         ? sample_triangle_light_by_area(e.triangle, reference, u)
                         : sample_triangle_light(e.triangle, options_.triangle, reference, receiver_normal, u);
      if (!t) return false;
      s.position = t->position;
      s.normal = e.triangle.normal;
      s.wi = t->wi;
      s.distance = t->distance;
      s.pdf = t->pdf_sr;
      if (e.textured) {
        s.has_uv = true;
        s.uv = barycentric_uv(e.uv0, e.duv1, e.duv2, t->barycentric);
      }
      return true;
    }
    case Kind::point:
    case Kind::spot: {
      const Vec3f d = e.position - reference;
      const float d2 = length_squared(d);
      if (!(d2 > 0.0f)) return false;
      s.distance = std::sqrt(d2);
      s.wi = d / s.distance;
      s.position = e.position;
      s.is_delta = true;
      s.pdf = 1.0f;
      // Intensity I (cd) → irradiance-like I / r² at the reference point.
      s.scale = 1.0f / d2;
      if (e.kind == Kind::spot) s.scale *= spot_falloff(dot(-s.wi, e.axis), e.cos_outer, e.cos_inner);
      if (!(s.scale > 0.0f)) return false;  // NaN too (not reachable today: the axis is sanitised above)
      return true;
    }
    case Kind::directional: {
      s.distance = std::numeric_limits<float>::infinity();
      if (e.cos_max >= 1.0f) {
        s.wi = -e.axis;
        s.is_delta = true;
        s.pdf = 1.0f;
        return true;  // scale 1: the spectrum is the illuminance
      }
      const Vec3f local = sample_uniform_cone(u, e.cos_max);
      s.wi = Frame::from_normal(-e.axis).to_world(local);
      s.pdf = uniform_cone_pdf(e.cos_max);
      s.scale = e.disc_radiance_scale;
      return true;
    }
    case Kind::environment: {
      s.distance = std::numeric_limits<float>::infinity();
      if (!e.texture) {
        // A constant sky is an emitter like the others: its colour (or spectrum) and its
        // luminance through the emission rule (render/color_context.h), scale 1.
        s.wi = sample_uniform_sphere(u);
        s.pdf = uniform_sphere_pdf();
        return true;
      }
      s.has_rgb = true;
      const PiecewiseConstant2D::Sample m = environment_distribution_.sample(u);
      const float jacobian = environment_solid_angle_per_uv_area(e.mapping, m.p);
      if (!(jacobian > 0.0f) || m.pdf <= 0.0f) return false;
      s.wi = normalize(e.map_to_world.apply_vector(environment_uv_to_direction(e.mapping, m.p)));
      s.pdf = m.pdf / jacobian;
      // The radiance at the sampled texel coordinates themselves, not at the direction
      // mapped back to them (an acos and an atan2 that return m.p up to rounding).
      s.rgb = environment_rgb_at(e, m.p);
      return true;
    }
  }
  return false;
}

float LightSampler::pdf_triangle(std::uint32_t mesh, std::uint32_t triangle, const Vec3f& reference,
                                 const Vec3f& position, const Vec3f& receiver_normal) const {
  if (mesh >= first_triangle_of_mesh_.size() || first_triangle_of_mesh_[mesh] < 0) return 0.0f;
  const auto index = static_cast<std::size_t>(first_triangle_of_mesh_[mesh]) + triangle;
  if (selection_pmf_[index] == 0.0f) return 0.0f;
  return selection_pmf_[index] *
         triangle_light_pdf(emitters_[index].triangle, options_.triangle, reference, receiver_normal, position);
}

std::optional<LightSampler::EscapedHit> LightSampler::escaped_hit(std::uint32_t index, const Vec3f& wi) const {
  const Emitter& e = emitters_[index];
  if (e.kind == Kind::environment) {
    // The direction's texel coordinates once, for both its pdf and its radiance.
    if (!e.texture) return EscapedHit{e.emitter, 1.0f, selection_pmf_[index] * uniform_sphere_pdf(), false, Vec3f()};
    const Vec2f uv = environment_direction_to_uv(e.mapping, map_direction(e, wi));
    return EscapedHit{e.emitter, 1.0f, selection_pmf_[index] * environment_pdf_at(e.mapping, uv), true,
                      environment_rgb_at(e, uv)};
  }
  if (e.kind != Kind::directional || e.cos_max >= 1.0f || dot(wi, -e.axis) < e.cos_max) return std::nullopt;
  return EscapedHit{e.emitter, e.disc_radiance_scale, selection_pmf_[index] * uniform_cone_pdf(e.cos_max), false,
                    Vec3f(0.0f)};
}

std::vector<LightSampler::EscapedHit> LightSampler::escaped(const Vec3f& wi) const {
  std::vector<EscapedHit> hits;
  visit_escaped(wi, [&](const EscapedHit& hit) { hits.push_back(hit); });
  return hits;
}

}  // namespace prism
