// The one translation unit that compiles tinyobjloader (Debian libtinyobjloader-dev's
// header; see loaders.cmake for why it is compiled here rather than linked).
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
