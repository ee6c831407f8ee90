#pragma once
// tinygltf with Prism's configuration: every translation unit must see the same macros,
// since the TinyGLTF class refers to the stb image hooks unless they are disabled.
#ifndef TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE
#endif
#ifndef TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#endif
#include <tiny_gltf.h>
