// The one translation unit that compiles stb_image_write (Debian libstb-dev's header), for
// encoding generated textures as PNG in memory (texture_png.h). No stdio: the scene
// writers put the bytes in files through AtomicFile or into a GLB's binary chunk.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#include <stb_image_write.h>
