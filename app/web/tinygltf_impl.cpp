// The browser build compiles tinygltf and stb_image from Debian's headers (cmake/web.cmake); the
// native build links Debian's libtinygltf and decodes images with OpenImageIO.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define STB_IMAGE_IMPLEMENTATION
#include <tiny_gltf.h>
