// tinyexr's implementation, compiled once, over zlib (in the browser, zlib compiled from Debian's
// source package by cmake/web.cmake).
#define TINYEXR_IMPLEMENTATION
#define TINYEXR_USE_MINIZ 0
#define TINYEXR_USE_THREAD 0
#define TINYEXR_USE_OPENMP 0
#include <tinyexr.h>
#include <zlib.h>
