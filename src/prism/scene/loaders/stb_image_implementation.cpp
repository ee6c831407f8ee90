// The one translation unit that compiles stb_image (Debian libstb-dev's header; see
// loaders.cmake for why it is compiled here rather than linked from libstb.so).
// Only the decoders Prism reads textures with (PNG, JPEG), and the Radiance .hdr one that
// tests/io/radiance_hdr_reader_test.cpp checks Prism's own .hdr reader against (the
// loaders never call it); no stdio, so every read goes through our own file handling and
// errors.
#define STB_IMAGE_IMPLEMENTATION
#define STBI_NO_STDIO
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_ONLY_HDR
#define STBI_FAILURE_USERMSG
#include <stb_image.h>
