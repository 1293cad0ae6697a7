# The libraries of the browser build (issue 29; scripts/build-web.sh configures it with emcmake).
# Emscripten's CMake toolchain searches only its own sysroot, so Debian's header-only packages (GLM,
# nlohmann-json, tinygltf, stb, tinyexr) are linked into a folder of the build tree and offered as targets of
# the names the native build finds; /usr/include itself would bring glibc's headers with it.
set(GBL_WEB_INCLUDE ${CMAKE_BINARY_DIR}/web-include)
file(MAKE_DIRECTORY ${GBL_WEB_INCLUDE})
foreach(entry glm nlohmann stb tiny_gltf.h tinyexr.h CLI)
  if(NOT EXISTS /usr/include/${entry})
    message(FATAL_ERROR "/usr/include/${entry} is missing: scripts/build-web.sh installs the packages")
  endif()
  if(NOT EXISTS ${GBL_WEB_INCLUDE}/${entry})
    file(CREATE_LINK /usr/include/${entry} ${GBL_WEB_INCLUDE}/${entry} SYMBOLIC)
  endif()
endforeach()

add_library(glm::glm INTERFACE IMPORTED)
target_include_directories(glm::glm SYSTEM INTERFACE ${GBL_WEB_INCLUDE})
add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED)
target_include_directories(nlohmann_json::nlohmann_json SYSTEM INTERFACE ${GBL_WEB_INCLUDE})
# tinygltf and stb_image are compiled here (Debian ships libtinygltf.so for the host only); stb_image
# also decodes the glTF textures, as OpenImageIO does natively.
add_library(gbl_web_tinygltf STATIC ${CMAKE_SOURCE_DIR}/app/web/tinygltf_impl.cpp)
target_include_directories(gbl_web_tinygltf SYSTEM PUBLIC ${GBL_WEB_INCLUDE} ${GBL_WEB_INCLUDE}/stb)
add_library(TinyGLTF::TinyGLTF ALIAS gbl_web_tinygltf)
# zlib for tinyexr (renderer/image), compiled from Debian's zlib source package, which
# scripts/build-web.sh unpacks (scripts/debian-source.sh): Emscripten's zlib port would download its
# sources at build time. Only the C files that compress() and uncompress() need.
set(GBL_WEB_ZLIB_DIR "" CACHE PATH "Debian's zlib sources (apt-get source zlib), compiled for the browser")
if(NOT EXISTS "${GBL_WEB_ZLIB_DIR}/inflate.c")
  message(FATAL_ERROR "GBL_WEB_ZLIB_DIR (${GBL_WEB_ZLIB_DIR}) holds no zlib sources: scripts/build-web.sh fetches them")
endif()
set(gbl_zlib_sources)
foreach(file adler32 compress crc32 deflate inffast inflate inftrees trees uncompr zutil)
  list(APPEND gbl_zlib_sources ${GBL_WEB_ZLIB_DIR}/${file}.c)
endforeach()
add_library(gbl_web_zlib STATIC ${gbl_zlib_sources})
target_include_directories(gbl_web_zlib SYSTEM PUBLIC ${GBL_WEB_ZLIB_DIR})
target_compile_options(gbl_web_zlib PRIVATE -w)
set_target_properties(gbl_web_zlib PROPERTIES UNITY_BUILD OFF)
# Emscripten's own GLFW 3 port (its header is in the sysroot; the port is a link setting).
add_library(glfw INTERFACE IMPORTED)
target_link_options(glfw INTERFACE -sUSE_GLFW=3)
add_library(Threads::Threads INTERFACE IMPORTED)
add_library(CLI11::CLI11 INTERFACE IMPORTED)
target_include_directories(CLI11::CLI11 SYSTEM INTERFACE ${GBL_WEB_INCLUDE})
# OpenImageIO and libepoxy have no browser build: empty targets of their names, so the libraries'
# link lines stay one list. Image files go through stb_image, stb_image_write and tinyexr here
# (renderer/image/image_io_stb.cpp); WebGL2's declarations come
# from Emscripten's GLES3 headers (renderer/gl/gl_api.h).
add_library(PkgConfig::OIIO INTERFACE IMPORTED)
target_link_libraries(PkgConfig::OIIO INTERFACE gbl_web_tinygltf)
add_library(PkgConfig::EPOXY INTERFACE IMPORTED)
# The code catches exceptions (json parsing, scene loading); Emscripten compiles them away unless asked.
add_compile_options(-fexceptions)
add_link_options(-fexceptions)
set(GBL_GL_LIBS "")
