/* tools/gbl_dump/gbl_dump.h compiled as C99: gbl_dump_gl_test calls this, so the C build's files are
 * checked as well as the C++ build's. */
#include <epoxy/gl.h>

#define GBL_DUMP_STATIC
#define GBL_DUMP_IMPLEMENTATION
#include "gbl_dump.h"

#include <string.h>

int gbl_dump_test_from_c(GLuint framebuffer, int width, int height, const char* dir, const float eye[3],
                         const float target[3], float fov_y_degrees, float near_plane, float far_plane, char* message,
                         size_t message_size);

/* LearnOpenGL's layout with the camera given by placement and lens rather than matrices. */
int gbl_dump_test_from_c(GLuint framebuffer, int width, int height, const char* dir, const float eye[3],
                         const float target[3], float fov_y_degrees, float near_plane, float far_plane, char* message,
                         size_t message_size) {
    gbl_dump_options o;
    gbl_dump_camera camera;
    gbl_dump_options_learnopengl(&o);
    memset(&camera, 0, sizeof camera);
    memcpy(camera.position, eye, sizeof camera.position);
    memcpy(camera.target, target, sizeof camera.target);
    camera.fov_y_degrees = fov_y_degrees;
    camera.near_plane = near_plane;
    camera.far_plane = far_plane;
    o.camera = &camera;
    return gbl_dump(framebuffer, width, height, dir, &o, message, message_size);
}
