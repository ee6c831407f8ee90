#include "prism/render/image_fingerprint.h"

#include <algorithm>

#include "prism/render/renderer.h"

namespace prism {
namespace {

// FNV-1a (Fowler, Noll, Vo) over raw bytes: stable across runs and platforms of the same
// endianness, which is all a fingerprint needs.
class Fnv1a {
 public:
  void bytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) hash_ = (hash_ ^ p[i]) * 0x100000001b3ull;
  }
  template <typename T>
  void value(const T& v) {
    bytes(&v, sizeof v);
  }
  // Only where `v` differs from its default, so that scenes without the field keep the
  // fingerprints of versions that did not hash it (and their checkpoints still resume).
  template <typename T>
  void value_if_changed(const T& v, const T& default_value) {
    if (v != default_value) value(v);
  }
  std::uint64_t digest() const { return hash_; }

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325ull;
};

void hash_spectrum(Fnv1a& h, const color::PiecewiseLinearSpectrum& s) {
  h.value(s.wavelengths_nm().size());
  h.bytes(s.wavelengths_nm().data(), s.wavelengths_nm().size_bytes());
  h.bytes(s.values().data(), s.values().size_bytes());
}

// What changes a scene's pixels beyond the fields image_fingerprint hashed from the start,
// each only where it differs from its default, so that scenes without it keep the
// fingerprints of earlier versions (and their checkpoints still resume): shading
// attributes of meshes, instances, textures (texels and addressing), the material fields
// the first version left out, and light shapes. A checkpoint of a scene that differs in any
// of them no longer resumes as the other.
// A vector's size and contents, only where it is not empty.
template <typename Vector>
void hash_vector_if_any(Fnv1a& h, const Vector& v) {
  if (v.empty()) return;
  h.value(v.size());
  h.bytes(v.data(), v.size() * sizeof(v[0]));
}

void hash_geometry_details(Fnv1a& h, const Scene& scene) {
  const auto vector_if_any = [&h](const auto& v) { hash_vector_if_any(h, v); };
  for (const TriangleMesh& mesh : scene.meshes) {
    vector_if_any(mesh.normals);
    vector_if_any(mesh.uvs);
    vector_if_any(mesh.tangents);
    vector_if_any(mesh.tangent_signs);
  }
  for (const Instance& instance : scene.instances) {
    h.value(instance.mesh);
    h.value(instance.object_to_world.m);
    h.value(instance.object_to_world.translation);
  }
  for (const TextureImage& t : scene.textures) {
    h.value(t.width);
    h.value(t.height);
    h.value(t.channels);
    vector_if_any(t.texels);
    vector_if_any(t.codes);
    vector_if_any(t.rgbe);
    vector_if_any(t.halves);
    h.value(t.encoding);
    for (float v : {t.offset_u, t.offset_v, t.scale_u, t.scale_v, t.rotation_radians}) h.value(v);
    h.value(t.wrap_u);
    h.value(t.wrap_v);
  }
}

void hash_material_details(Fnv1a& h, const Scene& scene) {
  const Material plain;
  for (const Material& m : scene.materials) {
    h.value_if_changed(m.base_color_texture, plain.base_color_texture);
    h.value_if_changed(m.metallic_roughness_texture, plain.metallic_roughness_texture);
    if (m.emission.texture != plain.emission.texture) h.value(m.emission.texture);
    if (m.emission.two_sided != plain.emission.two_sided) h.value(m.emission.two_sided);
    h.value_if_changed(m.anisotropy, plain.anisotropy);
    h.value_if_changed(m.anisotropy_rotation_rad, plain.anisotropy_rotation_rad);
    h.value_if_changed(m.anisotropy_texture, plain.anisotropy_texture);
    h.value_if_changed(m.microfacet, plain.microfacet);
    if (m.conductor_fresnel != plain.conductor_fresnel) {
      h.value(m.conductor_fresnel);
      h.bytes(m.conductor_name.data(), m.conductor_name.size());
    }
    if (m.dispersion != plain.dispersion) {
      h.value(m.dispersion);
      h.value(m.dispersion_coefficients);
    }
    h.value_if_changed(m.thin_walled, plain.thin_walled);
    h.value_if_changed(m.transmission, plain.transmission);
    if (m.alpha_mode != plain.alpha_mode) {
      h.value(m.alpha_mode);
      h.value(m.alpha_cutoff);
    }
    h.value_if_changed(m.opacity, plain.opacity);
    if (m.absorbs_inside()) {
      h.value(m.attenuation_color);
      h.value(m.attenuation_distance);
    }
    h.value_if_changed(m.specular, plain.specular);
    h.value_if_changed(m.specular_color, plain.specular_color);
    h.value_if_changed(m.specular_texture, plain.specular_texture);
    h.value_if_changed(m.specular_color_texture, plain.specular_color_texture);
    if (m.has_clearcoat()) {
      h.value(m.clearcoat);
      h.value(m.clearcoat_roughness);
      h.value(m.clearcoat_texture);
      h.value(m.clearcoat_roughness_texture);
      // Only where there is one, so coats without keep their earlier fingerprints.
      if (m.clearcoat_normal_texture != plain.clearcoat_normal_texture) {
        h.value(m.clearcoat_normal_texture);
        h.value(m.clearcoat_normal_scale);
      }
    }
    if (m.has_iridescence()) {
      h.value(m.iridescence);
      h.value(m.iridescence_ior);
      h.value(m.iridescence_thickness_min_nm);
      h.value(m.iridescence_thickness_max_nm);
      h.value(m.iridescence_texture);
      h.value(m.iridescence_thickness_texture);
    }
    if (m.has_sheen()) {
      h.value(m.sheen_color);
      h.value(m.sheen_roughness);
      h.value(m.sheen_color_texture);
      h.value(m.sheen_roughness_texture);
    }
  }
}

void hash_light_details(Fnv1a& h, const Scene& scene) {
  const Light point;
  for (const Light& l : scene.lights) {
    h.value_if_changed(l.color_space, point.color_space);
    if (l.type == LightType::spot) {
      h.value(l.spot_inner_angle_degrees);
      h.value(l.spot_outer_angle_degrees);
    }
    h.value_if_changed(l.angular_diameter_degrees, point.angular_diameter_degrees);
    if (l.type == LightType::environment) {
      h.value_if_changed(l.environment_texture, point.environment_texture);
      h.value_if_changed(l.environment_mapping, point.environment_mapping);
      if (!(l.environment_to_world == Transform{})) {
        h.value(l.environment_to_world.m);
        h.value(l.environment_to_world.translation);
      }
    }
  }
}

void hash_scene_details(Fnv1a& h, const Scene& scene) {
  hash_geometry_details(h, scene);
  hash_material_details(h, scene);
  hash_light_details(h, scene);
}

}  // namespace

std::uint64_t image_fingerprint(const Scene& scene, const RenderSettings& settings) {
  Fnv1a h;
  for (const auto& mesh : scene.meshes) {
    h.value(mesh.material);
    h.value(mesh.positions.size());
    h.bytes(mesh.positions.data(), mesh.positions.size() * sizeof(Vec3f));
    h.value(mesh.indices.size());
    h.bytes(mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t));
  }
  for (const auto& m : scene.materials) {
    h.value(m.type);
    h.value(m.base_color);
    h.value(m.roughness);
    h.value(m.metallic);
    h.value(m.ior);
    h.value(m.emission.color);
    h.value(m.emission.color_space);
    h.value(m.emission.luminance_nits);
    // Spectra given as data, only where there are some (so other scenes keep their fingerprints).
    for (const auto* spectrum : {&m.base_color_spectrum, &m.emission.spectrum})
      if (*spectrum) hash_spectrum(h, **spectrum);
    // Only for wide-gamut base colours, so other scenes keep their fingerprints.
    if (m.base_color_space != ColorPickerSpace::srgb) h.value(m.base_color_space);
    // Only with a normal or bump map, so other scenes keep their fingerprints; checkpoints
    // of such scenes from before these maps were applied no longer match.
    if (m.normal_texture >= 0) {
      h.value(m.normal_texture);
      h.value(m.normal_scale);
    }
    if (m.bump_texture >= 0) {
      h.value(m.bump_texture);
      h.value(m.bump_scale);
    }
  }
  const Camera& c = scene.camera;
  for (float v : {c.eye.x, c.eye.y, c.eye.z, c.target.x, c.target.y, c.target.z, c.up.x, c.up.y, c.up.z,
                  c.fov_degrees, c.aperture_radius, c.focus_distance})
    h.value(v);
  h.value(settings.width);
  h.value(settings.height);
  h.value(settings.seed);
  h.value(settings.path.max_depth);
  h.value(settings.path.russian_roulette_depth);
  h.value(settings.path.estimator);
  h.value(settings.path.sampler);
  // Only when not the default, so default renders keep the fingerprints of earlier versions
  // (every light-sampling option is unbiased, so resuming across them still converges).
  const LightSamplerOptions default_light;
  if (settings.path.light.triangle != default_light.triangle ||
      settings.path.light.reuse_selection_sample != default_light.reuse_selection_sample) {
    h.value(settings.path.light.triangle);
    h.value(settings.path.light.reuse_selection_sample);
  }
  if (settings.path.normal_mapping != NormalMapping::classic) h.value(settings.path.normal_mapping);  // as above
  h.value(settings.transport.kind);
  h.value(settings.transport.wavelengths);
  h.value(settings.transport.wavelength_strategy);
  h.value(settings.transport.stratify_first_wavelengths);
  h.value(settings.transport.upsampling);
  h.bytes(settings.transport.working_space.data(), settings.transport.working_space.size());
  // Reflectances became E-relative (jakob_hanika_target_xyz_matrix,
  // mallett_yuksel_weights_under_e; in RGB transport measured reflectances likewise): every
  // coloured spectral pixel changed, so checkpoints from before must not resume into it.
  constexpr std::uint32_t kReflectanceConvention = 2;
  if (settings.transport.kind == TransportKind::spectral ||
      std::any_of(scene.materials.begin(), scene.materials.end(),
                  [](const Material& m) { return m.base_color_spectrum.has_value(); }))
    h.value(kReflectanceConvention);
  for (const auto& l : scene.lights) {
    h.value(l.type);
    h.value(l.position);
    h.value(l.direction);
    h.value(l.color);
    h.value(l.intensity);
    if (l.spectrum) hash_spectrum(h, *l.spectrum);
  }
  hash_scene_details(h, scene);
  // Only when requested, so renders without AOVs keep the fingerprints of earlier versions.
  if (settings.aovs.any()) h.value(settings.aovs.bits());
  // The reference path tracer estimates the same image with other bits: only its renders
  // hash it, so wavefront renders keep their fingerprints.
  if (settings.integrator != IntegratorKind::wavefront) h.value(settings.integrator);
  // Adaptive sampling decides which pixels take which samples: only adaptive renders hash
  // its settings, so uniform renders keep their fingerprints.
  if (settings.adaptive.enabled()) {
    h.value(settings.adaptive.noise_threshold);
    h.value(settings.adaptive.min_samples);
    if (!settings.adaptive.dilate) h.value(settings.adaptive.dilate);
  }
  return h.digest();
}

}  // namespace prism
