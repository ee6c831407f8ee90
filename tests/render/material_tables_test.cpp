// MaterialTables::fixed_point: the shading point shading copies for a material that no
// texture varies. It must be the material's untextured_point, and must be refused for a
// material with any texture material_point() reads, or that texture would be ignored.
#include <gtest/gtest.h>

#include <cstring>
#include <iterator>
#include <vector>

#include "prism/render/material_bsdf.h"

namespace prism {
namespace {

Material layered_material() {
  Material m;
  m.type = MaterialType::metallic_roughness;
  m.roughness = 0.3f;
  m.metallic = 0.25f;
  m.clearcoat = 0.5f;
  m.clearcoat_roughness = 0.1f;
  m.sheen_color = Vec3f(0.2f, 0.3f, 0.4f);
  m.sheen_roughness = 0.6f;
  m.specular = 0.8f;
  m.specular_color = Vec3f(1.0f, 0.9f, 0.8f);
  m.iridescence = 0.7f;
  return m;
}

void expect_same_point(const MaterialPoint& a, const MaterialPoint& b) {
  // Every member is a float: equal bit patterns member by member.
  static_assert(sizeof(MaterialPoint) % sizeof(float) == 0);
  EXPECT_EQ(std::memcmp(&a, &b, sizeof(MaterialPoint)), 0);
}

TEST(MaterialTables, FixedPointIsTheUntexturedPoint) {
  Material m = layered_material();
  // Textures material_point() does not read leave the point fixed.
  m.base_color_texture = 0;
  m.normal_texture = 1;
  m.emission.texture = 2;
  const Material plain;  // the defaults
  const MaterialTables tables({m, plain});
  ASSERT_NE(tables.fixed_point(0), nullptr);
  expect_same_point(*tables.fixed_point(0), untextured_point(m));
  ASSERT_NE(tables.fixed_point(1), nullptr);
  expect_same_point(*tables.fixed_point(1), untextured_point(plain));
}

TEST(MaterialTables, AnyPointTextureMakesThePointVary) {
  int Material::*const slots[] = {
      &Material::metallic_roughness_texture, &Material::clearcoat_texture,   &Material::clearcoat_roughness_texture,
      &Material::sheen_color_texture,        &Material::sheen_roughness_texture, &Material::specular_texture,
      &Material::specular_color_texture,     &Material::iridescence_texture, &Material::iridescence_thickness_texture};
  for (std::size_t k = 0; k < std::size(slots); ++k) {
    Material m = layered_material();
    m.*slots[k] = 0;
    const MaterialTables tables({m});
    EXPECT_EQ(tables.fixed_point(0), nullptr) << "texture slot " << k << " of the list";
  }
}

TEST(MaterialTables, PlainDiffuseIsABareUntexturedLambertianLobe) {
  Material diffuse;
  diffuse.type = MaterialType::diffuse;
  diffuse.base_color = Vec3f(0.2f, 0.5f, 0.7f);
  EXPECT_TRUE(is_plain_diffuse(diffuse));
  Material lamp = diffuse;  // untextured emission changes nothing about the lobe
  lamp.emission.color = Vec3f(1.0f);
  lamp.emission.luminance_nits = 100.0f;
  EXPECT_TRUE(is_plain_diffuse(lamp));

  for (const MaterialType t : {MaterialType::mirror, MaterialType::conductor, MaterialType::dielectric,
                               MaterialType::metallic_roughness}) {
    Material m = diffuse;
    m.type = t;
    EXPECT_FALSE(is_plain_diffuse(m)) << "type " << static_cast<int>(t);
  }
  Material coated = diffuse;
  coated.clearcoat = 0.5f;
  EXPECT_FALSE(is_plain_diffuse(coated));
  Material sheened = diffuse;
  sheened.sheen_color = Vec3f(0.3f);
  EXPECT_FALSE(is_plain_diffuse(sheened));
  // Every texture slot, read by the lobe or not: the plain path reads none of them.
  int Material::*const slots[] = {
      &Material::base_color_texture,     &Material::normal_texture,          &Material::bump_texture,
      &Material::clearcoat_normal_texture, &Material::metallic_roughness_texture, &Material::clearcoat_texture,
      &Material::clearcoat_roughness_texture, &Material::sheen_color_texture, &Material::sheen_roughness_texture,
      &Material::specular_texture,       &Material::specular_color_texture,  &Material::iridescence_texture,
      &Material::iridescence_thickness_texture};
  for (std::size_t k = 0; k < std::size(slots); ++k) {
    Material m = diffuse;
    m.*slots[k] = 0;
    EXPECT_FALSE(is_plain_diffuse(m)) << "texture slot " << k << " of the list";
  }
  Material textured_lamp = lamp;
  textured_lamp.emission.texture = 0;
  EXPECT_FALSE(is_plain_diffuse(textured_lamp));
}

}  // namespace
}  // namespace prism
