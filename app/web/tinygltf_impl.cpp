// The browser build compiles tinygltf, stb_image and stb_image_write from Debian's headers
// (cmake/web.cmake); the native build links Debian's libtinygltf and reads and writes images with
// OpenImageIO.
#define TINYGLTF_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <tiny_gltf.h>
