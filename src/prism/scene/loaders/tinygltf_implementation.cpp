// The tinygltf implementation (Debian: libtinygltf-dev, a single header), compiled into
// prism so the sanitizer and fuzzer builds instrument it. Images are not decoded by
// tinygltf: gltf_scene.cpp's image callback keeps the encoded bytes and Prism's own
// texture reader (with its dimension limit) decodes them.
#define TINYGLTF_IMPLEMENTATION
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#endif
#include "prism/scene/loaders/tinygltf_config.h"
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
