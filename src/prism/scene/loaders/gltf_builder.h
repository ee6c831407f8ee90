#pragma once
// Internal to the glTF loader: turning a parsed tinygltf::Model into a Scene.
#include <exception>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "prism/scene/loaders/tinygltf_config.h"

#include "prism/scene/load_options.h"
#include "prism/scene/scene.h"
#include "prism/scene/texture_file.h"

namespace prism::loaders {

class GltfBuilder {
 public:
  GltfBuilder(const tinygltf::Model& model, std::string source, const std::filesystem::path& dir,
              const LoadOptions& options);
  Scene build();

 private:
  void check_extensions();
  void read_material_variants();
  int variant_material(const tinygltf::Value& mappings, int material, const std::string& where) const;
  void decode_images_in_parallel();
  void build_materials();
  Material make_material(const tinygltf::Material& m, int index);
  void read_volume(Material& m, const tinygltf::Value* volume, const std::string& where);
  void read_clearcoat(Material& m, const tinygltf::Value& clearcoat, const std::string& where);
  void read_specular(Material& m, const tinygltf::Value& specular, const std::string& where);
  void read_sheen(Material& m, const tinygltf::Value& sheen, const std::string& where);
  void read_iridescence(Material& m, const tinygltf::Value& iridescence, const std::string& where);
  void read_anisotropy(Material& m, const tinygltf::Value& anisotropy, const std::string& where);
  void read_dispersion(Material& m, const tinygltf::Value& dispersion, const std::string& where);
  int extension_texture(const tinygltf::Value& object, const char* key, TextureEncoding encoding,
                        const std::string& where);
  int texture(const tinygltf::TextureInfo& info, TextureEncoding encoding, const std::string& where);
  int texture(int texture_index, const tinygltf::ExtensionMap& extensions, TextureEncoding encoding, const std::string& where);
  void visit_node(int node, const Transform& parent, int depth);
  const std::vector<std::uint32_t>& mesh_primitives(int mesh);
  void add_camera(const tinygltf::Camera& camera, const Transform& to_world, const std::string& name);
  void add_light(int light, const Transform& to_world);
  std::string image_name(int source) const;  // the image's file name, or "<scene>#image<index>"
  [[noreturn]] void fail(const std::string& message) const;

  const tinygltf::Model& model_;
  std::string source_;
  std::filesystem::path dir_;
  LoadOptions options_;
  Scene scene_;
  std::map<std::pair<int, TextureEncoding>, int> image_textures_;
  // Images decoded ahead by decode_images_in_parallel, by (image, encoding): the texture,
  // or what decoding it threw, for texture() to take in its own order.
  struct DecodedImage {
    std::optional<TextureImage> image;
    std::exception_ptr error;
  };
  std::map<std::pair<int, TextureEncoding>, DecodedImage> decoded_images_;
  std::map<int, std::vector<std::uint32_t>> meshes_;  // glTF mesh → Prism mesh per primitive
  int default_material_ = -1;
  int selected_variant_ = -1;  // index into scene_.material_variants; -1: the default materials
  std::vector<bool> visited_;  // nodes already placed
  std::vector<std::string> warnings_;
};

}  // namespace prism::loaders
