/* gbl_dump.h: writes an OpenGL G-buffer (a framebuffer's colour attachments and its depth) to a folder
 * that `gbuffer-lab check` and gbuffer-lab's importer open, with a manifest describing it.
 *
 * A single header for C99 and C++, depending on nothing but the caller's GL loader. It uses OpenGL 3.3
 * core calls only: glBindFramebuffer(GL_READ_FRAMEBUFFER), glReadBuffer, glReadPixels,
 * glGetFramebufferAttachmentParameteriv, glCheckFramebufferStatus, glBindBuffer(GL_PIXEL_PACK_BUFFER),
 * glPixelStorei, glClampColor, glGetIntegerv and glGetError.
 *
 * USE
 *   In exactly one C or C++ file, after the GL header (glad, GLEW, epoxy ...):
 *       #define GBL_DUMP_IMPLEMENTATION
 *       #include "gbl_dump.h"
 *   Elsewhere, include it without the define. Define GBL_DUMP_STATIC as well to make every function
 *   static (private to that file).
 *
 *   After the geometry pass (LearnOpenGL's deferred chapter: gPosition, gNormal, gAlbedoSpec):
 *       gbl_dump_options o;
 *       gbl_dump_options_learnopengl(&o);   // attachments 0, 1, 2 and depth, shininess 16
 *       gbl_dump_camera cam = {0};
 *       cam.view = glm::value_ptr(view);    // the matrices the geometry pass used, column-major
 *       cam.projection = glm::value_ptr(projection);
 *       gbl_dump_lights lights = {0};
 *       lights.count = (int)lightPositions.size();
 *       lights.positions = &lightPositions[0].x;  // count x 3 floats
 *       lights.colors = &lightColors[0].x;
 *       lights.linear = 0.7f; lights.quadratic = 1.8f;
 *       o.camera = &cam; o.lights = &lights;
 *       char msg[1024];
 *       if (gbl_dump(gBuffer, SCR_WIDTH, SCR_HEIGHT, "gbuffer-dump", &o, msg, sizeof msg) != GBL_DUMP_OK)
 *           fprintf(stderr, "%s\n", msg);
 *   then, in a shell: gbuffer-lab check gbuffer-dump
 *
 * API
 *   int gbl_dump(GLuint framebuffer, int width, int height, const char *dir,
 *                const gbl_dump_options *options, char *message, size_t message_size);
 *     Reads colour attachments 0 .. options->color_count - 1 of `framebuffer` (and its depth when
 *     options->depth) over width x height pixels from the lower-left corner, writes one file per
 *     attachment into the existing folder `dir`, and writes dir/manifest.json last. Returns GBL_DUMP_OK
 *     (0) or one of the nonzero GBL_DUMP_* codes below; `message` (may be NULL) receives one sentence:
 *     what went wrong, or what was written. Never aborts, never prints. The caller's GL state is as
 *     before on return (read framebuffer and its read buffer, pixel pack buffer, pack alignment, row
 *     length and skips, read clamping). width and height must be the attachments' size: GL gives no
 *     error for pixels outside them, only undefined values. A multisampled framebuffer is refused by GL
 *     (resolve it with glBlitFramebuffer first).
 *   void gbl_dump_options_defaults(gbl_dump_options *o);
 *     Nothing assigned: every role -1, 1 colour attachment, no depth, world space, float normals.
 *   void gbl_dump_options_learnopengl(gbl_dump_options *o);
 *     LearnOpenGL's layout: gPosition (0, world position), gNormal (1, world normal, stored as is),
 *     gAlbedoSpec (2, albedo in rgb, specular intensity in a), depth; shininess 16, its shading.
 *
 * FILES
 *   Each attachment is read in the type its storage needs and written in a format without
 *   dependencies:
 *     unsigned-normalised storage of at most 8 bits (RGBA8, SRGB8_ALPHA8 ...): GL_UNSIGNED_BYTE into
 *       PPM (P6) or PGM (P5) with maximum 255;
 *     everything else (RGB16F, RGBA32F, R11F_G11F_B10F, signed-normalised, RGBA16, RGB10_A2): GL_FLOAT
 *       into PFM (little-endian, negative scale), "PF" for 2 to 4 channels, "Pf" for 1. A 16- or 10-bit
 *       level is exact as a float, so nothing is lost, but a reader then sees 32-bit float storage.
 *       (16-bit PPM would say what the storage is, but OpenImageIO 2.4 reads some of its levels one
 *       low: 49151 as 49150.)
 *   Integer storage (R32UI ...) is refused. PPM and PFM hold at most three channels: a 2-channel
 *   attachment is padded with a zero third channel, and a 4-channel one writes its alpha to a second,
 *   one-channel file, NAME_a.pfm or NAME_a.pgm. Depth is read as GL_FLOAT into depth.pfm.
 *
 *   Orientation: every file is written the right way up by its own format's definition, so any viewer
 *   and gbuffer-lab show it as the screen did. PFM stores rows bottom to top, which is the order
 *   glReadPixels returns them in, so float rows are written as read; PPM and PGM store rows top to
 *   bottom, so 8-bit rows are written in reverse. The manifest therefore says "flip_y": false.
 *
 * MANIFEST
 *   dir/manifest.json follows docs/import.md (format "gbuffer-lab-gbuffer", version 1): the files and
 *   channels of the position, normal, albedo, specular, emissive and occlusion roles named in the
 *   options (the last two optional: the reader takes emission 0 and occlusion 1), depth (window
 *   convention, [0, 1]), the camera and the lights when given. Position is "from_depth" when no
 *   attachment holds it but depth and the camera are given. Depth needs near and far: without a camera
 *   the depth file is written but left out of the manifest. An albedo attachment with sRGB storage is
 *   marked "encoding": "srgb", and so is an emissive one. Attachments with no role are written but not
 *   named in the manifest.
 *   The manifest is a skeleton: edit it when a role or space differs (docs/import.md lists the fields).
 */
#ifndef GBL_DUMP_H
#define GBL_DUMP_H

#include <stddef.h>

#ifdef GBL_DUMP_STATIC
#if defined(__GNUC__) || defined(__clang__)
#define GBL_DUMP_DEF static __attribute__((unused)) /* a file may call only some of them */
#else
#define GBL_DUMP_DEF static
#endif
#else
#ifdef __cplusplus
#define GBL_DUMP_DEF extern "C"
#else
#define GBL_DUMP_DEF extern
#endif
#endif

#define GBL_DUMP_MAX_COLOR 8

/* Return codes of gbl_dump. */
enum {
    GBL_DUMP_OK = 0,
    GBL_DUMP_BAD_ARGUMENT = 1,    /* an argument or option is out of range */
    GBL_DUMP_BAD_FRAMEBUFFER = 2, /* incomplete, a missing attachment, a format that cannot be written */
    GBL_DUMP_GL_ERROR = 3,        /* GL raised an error while reading */
    GBL_DUMP_WRITE_FAILED = 4,    /* a file could not be written */
    GBL_DUMP_OUT_OF_MEMORY = 5
};

/* The camera of the geometry pass: both matrices, or (when either is NULL) its placement and lens. */
typedef struct gbl_dump_camera {
    const float* view;       /* 16 floats, column-major (glm::value_ptr; glUniformMatrix4fv untransposed) */
    const float* projection; /* 16 floats, column-major */
    float position[3];       /* used when a matrix is NULL; target - position is the viewing direction */
    float target[3];
    float up[3];         /* all zero: (0, 1, 0) */
    float fov_y_degrees; /* vertical field of view; the aspect ratio is the frame's */
    float near_plane;    /* required without matrices; with them, optional (0: read from a */
    float far_plane;     /* perspective projection) and written as the depth's near and far */
} gbl_dump_camera;

/* Point lights as a LearnOpenGL-style program uploads them: constant term 1. */
typedef struct gbl_dump_lights {
    int count;
    const float* positions; /* count x 3 floats, world space */
    const float* colors;    /* count x 3 floats */
    float linear;           /* for every light, unless linear_each is given */
    float quadratic;
    const float* linear_each; /* count floats, or NULL */
    const float* quadratic_each;
} gbl_dump_lights;

typedef struct gbl_dump_options {
    int color_count;                       /* colour attachments read: GL_COLOR_ATTACHMENT0 + 0 .. count - 1 */
    const char* names[GBL_DUMP_MAX_COLOR]; /* file names without extension; NULL: "color0", "color1" ... */
    int depth;                             /* nonzero: read the depth attachment into depth.pfm */
    /* Which colour attachment holds what (an index below color_count, or -1): the manifest's roles. */
    int position;
    int normal; /* the manifest needs one */
    int albedo; /* its r, g, b */
    int specular;
    int specular_channel;          /* 0 .. 3: r, g, b or a of the specular attachment */
    const char* position_space;    /* "world" or "view"; NULL: world */
    const char* normal_space;      /* "world" or "view"; NULL: world */
    const char* normal_encoding;   /* "float", "biased" (0.5 n + 0.5) or "octahedral"; NULL: float */
    float shininess;               /* > 0: written; 0: the reader's default */
    const char* shading;           /* "learnopengl", "gbuffer-lab" or NULL (the reader's default) */
    const gbl_dump_camera* camera; /* NULL: none */
    const gbl_dump_lights* lights; /* NULL: none */
    /* Optional roles (an index below color_count, or -1; gbl_dump_options_defaults sets -1): without
     * them the reader takes emission 0 and occlusion 1. */
    int emissive;          /* its r, g, b: emitted radiance, linear (or sRGB storage, marked so) */
    int occlusion;         /* ambient occlusion, 1 = unoccluded */
    int occlusion_channel; /* 0 .. 3: r, g, b or a of the occlusion attachment */
} gbl_dump_options;

GBL_DUMP_DEF void gbl_dump_options_defaults(gbl_dump_options* o);
GBL_DUMP_DEF void gbl_dump_options_learnopengl(gbl_dump_options* o);
GBL_DUMP_DEF int gbl_dump(GLuint framebuffer, int width, int height, const char* dir, const gbl_dump_options* options,
                          char* message, size_t message_size);

#endif /* GBL_DUMP_H */

/* ---------------------------------------------------------------------------------------------- */

#ifdef GBL_DUMP_IMPLEMENTATION
#ifndef GBL_DUMP_IMPLEMENTATION_DONE
#define GBL_DUMP_IMPLEMENTATION_DONE

#include <errno.h>
#include <float.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* How one attachment is read back and stored. */
typedef struct gbl_dump_att_ {
    int channels;   /* 1 .. 4, from the attachment's component sizes */
    int kind;       /* 0: float (PFM), 1: 8-bit (PPM/PGM) */
    int srgb;       /* the storage is sRGB-encoded */
    char stem[256]; /* file name without extension */
} gbl_dump_att_;

typedef struct gbl_dump_ctx_ {
    char* message;
    size_t message_size;
} gbl_dump_ctx_;

/* Puts one sentence into the caller's message buffer and returns `code`. */
static int gbl_dump_say_(gbl_dump_ctx_* c, int code, const char* fmt, ...) {
    if (c->message && c->message_size > 0) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(c->message, c->message_size, fmt, ap);
        va_end(ap);
    }
    return code;
}

static const char* gbl_dump_gl_error_name_(GLenum e) {
    switch (e) {
        case GL_INVALID_ENUM:
            return "GL_INVALID_ENUM";
        case GL_INVALID_VALUE:
            return "GL_INVALID_VALUE";
        case GL_INVALID_OPERATION:
            return "GL_INVALID_OPERATION";
        case GL_INVALID_FRAMEBUFFER_OPERATION:
            return "GL_INVALID_FRAMEBUFFER_OPERATION";
        case GL_OUT_OF_MEMORY:
            return "GL_OUT_OF_MEMORY";
        default:
            return "an unknown GL error";
    }
}

static const char* gbl_dump_status_name_(GLenum s) {
    switch (s) {
        case GL_FRAMEBUFFER_UNDEFINED:
            return "GL_FRAMEBUFFER_UNDEFINED";
        case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT:
            return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
        case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
            return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
        case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER:
            return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
        case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER:
            return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
        case GL_FRAMEBUFFER_UNSUPPORTED:
            return "GL_FRAMEBUFFER_UNSUPPORTED";
        case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE:
            return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
        case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS:
            return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
        default:
            return "an unknown status";
    }
}

static int gbl_dump_little_endian_(void) {
    unsigned int one = 1;
    unsigned char b;
    memcpy(&b, &one, 1);
    return b == 1;
}

/* dir/stem.ext into out; 0 when it does not fit. */
static int gbl_dump_path_(char* out, size_t size, const char* dir, const char* stem, const char* ext) {
    int n = snprintf(out, size, "%s/%s%s", dir, stem, ext);
    return n > 0 && (size_t)n < size;
}

/* Writes one plane of a read-back attachment: `first` and `count` select channels of `stride`. Float
 * rows go out as read (bottom to top, PFM's order); 8-bit rows in reverse (PPM's top to bottom). */
static int gbl_dump_write_file_(gbl_dump_ctx_* c, const char* path, const void* pixels, int kind, int width, int height,
                                int stride, int first, int count) {
    int out_channels = count == 1 ? 1 : 3;
    size_t sample = kind == 0 ? 4 : 1;
    size_t row_bytes = (size_t)width * (size_t)out_channels * sample;
    unsigned char* row = (unsigned char*)malloc(row_bytes);
    FILE* f;
    int y, x, k, ok = 1, swap = !gbl_dump_little_endian_();
    if (!row) return gbl_dump_say_(c, GBL_DUMP_OUT_OF_MEMORY, "gbl_dump: out of memory writing %s", path);
    f = fopen(path, "wb");
    if (!f) {
        int e = errno;
        free(row);
        return gbl_dump_say_(c, GBL_DUMP_WRITE_FAILED, "gbl_dump: cannot write %s (%s)", path, strerror(e));
    }
    if (kind == 0)
        ok = fprintf(f, "%s\n%d %d\n-1.0\n", out_channels == 1 ? "Pf" : "PF", width, height) > 0;
    else
        ok = fprintf(f, "%s\n%d %d\n255\n", out_channels == 1 ? "P5" : "P6", width, height) > 0;
    for (y = 0; ok && y < height; ++y) {
        int src_row = kind == 0 ? y : height - 1 - y;
        size_t base = (size_t)src_row * (size_t)width * (size_t)stride;
        for (x = 0; x < width; ++x)
            for (k = 0; k < out_channels; ++k) {
                size_t src = base + (size_t)x * (size_t)stride + (size_t)(first + k);
                unsigned char* dst = row + ((size_t)x * (size_t)out_channels + (size_t)k) * sample;
                int have = k < count;
                if (kind == 0) {
                    float v = have ? ((const float*)pixels)[src] : 0.0f;
                    unsigned char b[4];
                    memcpy(b, &v, 4);
                    if (swap) { /* PFM's negative scale: little-endian */
                        dst[0] = b[3], dst[1] = b[2], dst[2] = b[1], dst[3] = b[0];
                    } else {
                        memcpy(dst, b, 4);
                    }
                } else {
                    dst[0] = have ? ((const unsigned char*)pixels)[src] : 0;
                }
            }
        ok = fwrite(row, 1, row_bytes, f) == row_bytes;
    }
    free(row);
    if (fclose(f) != 0) ok = 0;
    if (!ok) return gbl_dump_say_(c, GBL_DUMP_WRITE_FAILED, "gbl_dump: writing %s failed (disk full?)", path);
    return GBL_DUMP_OK;
}

/* --- the manifest -------------------------------------------------------------------------------- */

/* A number as JSON: shortest round-tripping form, '.' as the decimal mark whatever the C locale. */
static void gbl_dump_json_number_(FILE* f, float v) {
    char buf[64];
    char* p;
    snprintf(buf, sizeof buf, "%.9g", (double)v);
    for (p = buf; *p; ++p)
        if (*p == ',') *p = '.';
    fputs(buf, f);
}

static void gbl_dump_json_string_(FILE* f, const char* s) {
    fputc('"', f);
    for (; *s; ++s) {
        unsigned char ch = (unsigned char)*s;
        if (ch == '"' || ch == '\\')
            fprintf(f, "\\%c", ch);
        else if (ch < 0x20)
            fprintf(f, "\\u%04x", ch);
        else
            fputc(ch, f);
    }
    fputc('"', f);
}

static void gbl_dump_json_floats_(FILE* f, const float* v, int n) {
    int i;
    fputc('[', f);
    for (i = 0; i < n; ++i) {
        if (i) fputs(", ", f);
        gbl_dump_json_number_(f, v[i]);
    }
    fputc(']', f);
}

/* "file" and the channel key of attachment `a`'s channels [first, first + count): channel 3 lives in
 * the NAME_a file. */
static void gbl_dump_json_image_(FILE* f, const gbl_dump_att_* a, const char* key, int first, int count) {
    static const char letters[] = "rgba";
    char name[300];
    int k;
    const char* ext = a->kind == 0 ? ".pfm" : (a->channels == 1 ? ".pgm" : ".ppm");
    if (first == 3) {
        snprintf(name, sizeof name, "%s_a%s", a->stem, a->kind == 0 ? ".pfm" : ".pgm");
        first = 0;
    } else {
        snprintf(name, sizeof name, "%s%s", a->stem, ext);
    }
    fputs("\"file\": ", f);
    gbl_dump_json_string_(f, name);
    fprintf(f, ", \"%s\": \"", key);
    for (k = 0; k < count; ++k) fputc(letters[first + k], f);
    fputc('"', f);
}

static int gbl_dump_finite_(const float* v, int n) {
    int i;
    for (i = 0; i < n; ++i)
        if (!(v[i] <= FLT_MAX && v[i] >= -FLT_MAX)) return 0; /* NaN fails both */
    return 1;
}

static int gbl_dump_write_manifest_(gbl_dump_ctx_* c, const char* dir, const gbl_dump_options* o,
                                    const gbl_dump_att_* att, int* depth_listed) {
    char path[4096];
    FILE* f;
    const gbl_dump_camera* cam = o->camera;
    const gbl_dump_lights* l = o->lights;
    int i, ok, has_near_far = cam && cam->near_plane > 0.0f && cam->far_plane > cam->near_plane;
    if (!gbl_dump_path_(path, sizeof path, dir, "manifest", ".json"))
        return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT, "gbl_dump: the folder name is too long");
    f = fopen(path, "wb");
    if (!f) {
        int e = errno;
        return gbl_dump_say_(c, GBL_DUMP_WRITE_FAILED, "gbl_dump: cannot write %s (%s)", path, strerror(e));
    }
    fputs("{\n  \"format\": \"gbuffer-lab-gbuffer\", \"version\": 1,\n", f);
    fputs("  \"flip_y\": false", f); /* every file is right way up by its format (see FILES above) */
    if (o->shininess > 0.0f) {
        fputs(", \"shininess\": ", f);
        gbl_dump_json_number_(f, o->shininess);
    }
    if (o->shading) {
        fputs(", \"shading\": ", f);
        gbl_dump_json_string_(f, o->shading);
    }
    *depth_listed = o->depth && cam != NULL;
    if (o->position >= 0) {
        fputs(",\n  \"position\": {", f);
        gbl_dump_json_image_(f, &att[o->position], "channels", 0, 3);
        fprintf(f, ", \"space\": \"%s\"}", o->position_space ? o->position_space : "world");
    } else if (*depth_listed) {
        fputs(",\n  \"position\": {\"from_depth\": true}", f);
    }
    fputs(",\n  \"normal\": {", f);
    {
        int octahedral = o->normal_encoding && strcmp(o->normal_encoding, "octahedral") == 0;
        gbl_dump_json_image_(f, &att[o->normal], "channels", 0, octahedral ? 2 : 3);
    }
    fprintf(f, ", \"encoding\": \"%s\", \"space\": \"%s\"}", o->normal_encoding ? o->normal_encoding : "float",
            o->normal_space ? o->normal_space : "world");
    if (o->albedo >= 0) {
        fputs(",\n  \"albedo\": {", f);
        gbl_dump_json_image_(f, &att[o->albedo], "channels", 0, 3);
        fprintf(f, ", \"encoding\": \"%s\"}", att[o->albedo].srgb ? "srgb" : "linear");
    }
    if (o->specular >= 0) {
        fputs(",\n  \"specular\": {", f);
        gbl_dump_json_image_(f, &att[o->specular], "channel", o->specular_channel, 1);
        fputc('}', f);
    }
    if (o->emissive >= 0) {
        fputs(",\n  \"emissive\": {", f);
        gbl_dump_json_image_(f, &att[o->emissive], "channels", 0, 3);
        fprintf(f, ", \"encoding\": \"%s\"}", att[o->emissive].srgb ? "srgb" : "linear");
    }
    if (o->occlusion >= 0) {
        fputs(",\n  \"occlusion\": {", f);
        gbl_dump_json_image_(f, &att[o->occlusion], "channel", o->occlusion_channel, 1);
        fputc('}', f);
    }
    if (*depth_listed) {
        fputs(",\n  \"depth\": {\"file\": \"depth.pfm\", \"channel\": \"r\", \"convention\": \"window\"", f);
        if (has_near_far) {
            fputs(", \"near\": ", f);
            gbl_dump_json_number_(f, cam->near_plane);
            fputs(", \"far\": ", f);
            gbl_dump_json_number_(f, cam->far_plane);
        }
        fputc('}', f);
    }
    if (cam) {
        fputs(",\n  \"camera\": {", f);
        if (cam->view && cam->projection) {
            fputs("\"matrix_layout\": \"column-major\",\n    \"view\": ", f);
            gbl_dump_json_floats_(f, cam->view, 16);
            fputs(",\n    \"projection\": ", f);
            gbl_dump_json_floats_(f, cam->projection, 16);
        } else {
            static const float y_up[3] = {0.0f, 1.0f, 0.0f};
            const float* up = (cam->up[0] == 0.0f && cam->up[1] == 0.0f && cam->up[2] == 0.0f) ? y_up : cam->up;
            fputs("\"position\": ", f);
            gbl_dump_json_floats_(f, cam->position, 3);
            fputs(", \"target\": ", f);
            gbl_dump_json_floats_(f, cam->target, 3);
            fputs(", \"up\": ", f);
            gbl_dump_json_floats_(f, up, 3);
            fputs(",\n    \"fov_y_degrees\": ", f);
            gbl_dump_json_number_(f, cam->fov_y_degrees);
            fputs(", \"near\": ", f);
            gbl_dump_json_number_(f, cam->near_plane);
            fputs(", \"far\": ", f);
            gbl_dump_json_number_(f, cam->far_plane);
        }
        fputc('}', f);
    }
    if (l && l->count > 0) {
        fputs(",\n  \"lights\": {\"positions\": [", f);
        for (i = 0; i < l->count; ++i) {
            if (i) fputs(", ", f);
            gbl_dump_json_floats_(f, l->positions + 3 * i, 3);
        }
        fputs("],\n    \"colors\": [", f);
        for (i = 0; i < l->count; ++i) {
            if (i) fputs(", ", f);
            gbl_dump_json_floats_(f, l->colors + 3 * i, 3);
        }
        fputs("],\n    \"linear\": ", f);
        if (l->linear_each)
            gbl_dump_json_floats_(f, l->linear_each, l->count);
        else
            gbl_dump_json_number_(f, l->linear);
        fputs(", \"quadratic\": ", f);
        if (l->quadratic_each)
            gbl_dump_json_floats_(f, l->quadratic_each, l->count);
        else
            gbl_dump_json_number_(f, l->quadratic);
        fputc('}', f);
    }
    fputs("\n}\n", f);
    ok = !ferror(f);
    if (fclose(f) != 0) ok = 0;
    if (!ok) return gbl_dump_say_(c, GBL_DUMP_WRITE_FAILED, "gbl_dump: writing %s failed (disk full?)", path);
    return GBL_DUMP_OK;
}

/* --- checks of the caller's options --------------------------------------------------------------- */

static int gbl_dump_one_of_(const char* s, const char* a, const char* b, const char* c3) {
    return s == NULL || strcmp(s, a) == 0 || strcmp(s, b) == 0 || (c3 && strcmp(s, c3) == 0);
}

static int gbl_dump_check_options_(gbl_dump_ctx_* c, const gbl_dump_options* o, int width, int height,
                                   const char* dir) {
    int i, j;
    const int roles[6] = {o->position, o->normal, o->albedo, o->specular, o->emissive, o->occlusion};
    static const char* const role_names[6] = {"position", "normal", "albedo", "specular", "emissive", "occlusion"};
    if (!dir || !*dir) return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT, "gbl_dump: dir must name an existing folder");
    if (width <= 0 || height <= 0 || width > 65536 || height > 65536)
        return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT, "gbl_dump: width and height must be 1 to 65536 (got %dx%d)",
                             width, height);
    if (o->color_count < 1 || o->color_count > GBL_DUMP_MAX_COLOR)
        return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT, "gbl_dump: options.color_count must be 1 to %d (got %d)",
                             GBL_DUMP_MAX_COLOR, o->color_count);
    for (i = 0; i < 6; ++i)
        if (roles[i] < -1 || roles[i] >= o->color_count)
            return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT,
                                 "gbl_dump: options.%s must be -1 or a colour attachment below color_count %d (got %d)",
                                 role_names[i], o->color_count, roles[i]);
    if (o->normal < 0)
        return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT,
                             "gbl_dump: options.normal must name the colour attachment holding normals (the manifest "
                             "needs one)");
    if (o->position < 0 && !(o->depth && o->camera))
        return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT,
                             "gbl_dump: options.position must name the colour attachment holding positions, or "
                             "options.depth and options.camera be given to rebuild them (the manifest needs one)");
    if (o->specular >= 0 && (o->specular_channel < 0 || o->specular_channel > 3))
        return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT, "gbl_dump: options.specular_channel must be 0 to 3 (got %d)",
                             o->specular_channel);
    if (o->occlusion >= 0 && (o->occlusion_channel < 0 || o->occlusion_channel > 3))
        return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT, "gbl_dump: options.occlusion_channel must be 0 to 3 (got %d)",
                             o->occlusion_channel);
    if (!gbl_dump_one_of_(o->position_space, "world", "view", NULL) ||
        !gbl_dump_one_of_(o->normal_space, "world", "view", NULL))
        return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT,
                             "gbl_dump: options.position_space and normal_space must be \"world\" or \"view\"");
    if (!gbl_dump_one_of_(o->normal_encoding, "float", "biased", "octahedral"))
        return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT,
                             "gbl_dump: options.normal_encoding must be \"float\", \"biased\" or \"octahedral\" "
                             "(got \"%s\")",
                             o->normal_encoding);
    if (!gbl_dump_one_of_(o->shading, "learnopengl", "gbuffer-lab", NULL))
        return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT,
                             "gbl_dump: options.shading must be \"learnopengl\", \"gbuffer-lab\" or NULL (got \"%s\")",
                             o->shading);
    if (!(o->shininess >= 0.0f) || !gbl_dump_finite_(&o->shininess, 1))
        return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT, "gbl_dump: options.shininess must be 0 or a positive number");
    for (i = 0; i < o->color_count; ++i) {
        const char* n = o->names[i];
        if (n && (!*n || strchr(n, '/') || strchr(n, '\\') || strlen(n) > 200))
            return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT,
                                 "gbl_dump: options.names[%d] must be a plain file name of 1 to 200 characters, "
                                 "without a folder (got \"%s\")",
                                 i, n);
        for (j = 0; j < i; ++j)
            if (n && o->names[j] && strcmp(n, o->names[j]) == 0)
                return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT,
                                     "gbl_dump: options.names[%d] and names[%d] are both \"%s\": one file would "
                                     "overwrite the other",
                                     j, i, n);
        if (n && strcmp(n, "depth") == 0 && o->depth)
            return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT,
                                 "gbl_dump: options.names[%d] is \"depth\", the depth attachment's file name", i);
    }
    if (o->camera) {
        const gbl_dump_camera* cam = o->camera;
        if (cam->view && cam->projection) {
            if (!gbl_dump_finite_(cam->view, 16) || !gbl_dump_finite_(cam->projection, 16))
                return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT, "gbl_dump: camera.view or projection holds NaN or Inf");
        } else {
            if (!gbl_dump_finite_(cam->position, 3) || !gbl_dump_finite_(cam->target, 3) ||
                !gbl_dump_finite_(cam->up, 3))
                return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT,
                                     "gbl_dump: camera.position, target or up holds NaN or Inf");
            if (!(cam->fov_y_degrees >= 1.0f && cam->fov_y_degrees <= 179.0f))
                return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT,
                                     "gbl_dump: camera.fov_y_degrees must be 1 to 179 (got %g); or give view and "
                                     "projection",
                                     (double)cam->fov_y_degrees);
            if (!(cam->near_plane > 0.0f && cam->far_plane > cam->near_plane) || !gbl_dump_finite_(&cam->far_plane, 1))
                return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT,
                                     "gbl_dump: camera.near_plane must be > 0 and far_plane greater (got %g and %g)",
                                     (double)cam->near_plane, (double)cam->far_plane);
        }
    }
    if (o->lights && o->lights->count != 0) {
        const gbl_dump_lights* l = o->lights;
        if (l->count < 0 || !l->positions || !l->colors)
            return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT,
                                 "gbl_dump: lights.count must be >= 0, with positions and colors of count x 3 floats");
        for (i = 0; i < l->count; ++i) {
            const float lin = l->linear_each ? l->linear_each[i] : l->linear;
            const float quad = l->quadratic_each ? l->quadratic_each[i] : l->quadratic;
            if (!gbl_dump_finite_(l->positions + 3 * i, 3) || !gbl_dump_finite_(l->colors + 3 * i, 3) ||
                l->colors[3 * i] < 0.0f || l->colors[3 * i + 1] < 0.0f || l->colors[3 * i + 2] < 0.0f ||
                !(lin >= 0.0f) || !(quad >= 0.0f) || !gbl_dump_finite_(&lin, 1) || !gbl_dump_finite_(&quad, 1))
                return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT,
                                     "gbl_dump: light %d needs a finite position, a colour >= 0 and linear and "
                                     "quadratic terms >= 0",
                                     i);
        }
    }
    return GBL_DUMP_OK;
}

/* --- reading the framebuffer ---------------------------------------------------------------------- */

/* The attachment's channels and storage, from its component type and sizes. */
static int gbl_dump_describe_(gbl_dump_ctx_* c, GLenum attachment, int index, gbl_dump_att_* a) {
    GLint type = GL_NONE, component = GL_NONE, encoding = GL_LINEAR, size[4] = {0, 0, 0, 0}, widest = 0;
    static const GLenum size_names[4] = {GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE, GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE,
                                         GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE, GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE};
    int k;
    glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
                                          &type);
    if (type == GL_NONE)
        return gbl_dump_say_(
            c, GBL_DUMP_BAD_FRAMEBUFFER,
            "gbl_dump: colour attachment %d has nothing attached (options.color_count is %d too many?)", index,
            index + 1);
    glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE,
                                          &component);
    glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING,
                                          &encoding);
    for (k = 0; k < 4; ++k) {
        glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, attachment, size_names[k], &size[k]);
        if (size[k] > 0) a->channels = k + 1;
        if (size[k] > widest) widest = size[k];
    }
    a->srgb = encoding == GL_SRGB;
    if (a->channels == 0)
        return gbl_dump_say_(c, GBL_DUMP_BAD_FRAMEBUFFER, "gbl_dump: colour attachment %d has no colour channels",
                             index);
    if (component == GL_UNSIGNED_NORMALIZED && widest <= 8)
        a->kind = 1;
    else if (component == GL_FLOAT || component == GL_SIGNED_NORMALIZED || component == GL_UNSIGNED_NORMALIZED)
        a->kind = 0;
    else
        return gbl_dump_say_(c, GBL_DUMP_BAD_FRAMEBUFFER,
                             "gbl_dump: colour attachment %d has integer storage, which this helper does not read "
                             "(float and normalised formats only)",
                             index);
    return GBL_DUMP_OK;
}

/* Reads attachment `a` (or depth) and writes its file(s). */
static int gbl_dump_read_write_(gbl_dump_ctx_* c, const char* dir, const gbl_dump_att_* a, int is_depth, int width,
                                int height) {
    static const GLenum formats[4] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
    size_t sample = a->kind == 0 ? 4 : 1;
    size_t bytes = (size_t)width * (size_t)height * (size_t)a->channels * sample;
    void* pixels = malloc(bytes);
    char path[4096];
    GLenum err;
    int rc;
    const char* ext = a->kind == 0 ? ".pfm" : (a->channels == 1 ? ".pgm" : ".ppm");
    if (!pixels)
        return gbl_dump_say_(c, GBL_DUMP_OUT_OF_MEMORY, "gbl_dump: out of memory reading %s (%lu bytes)", a->stem,
                             (unsigned long)bytes);
    glReadPixels(0, 0, width, height, is_depth ? GL_DEPTH_COMPONENT : formats[a->channels - 1],
                 a->kind == 0 ? GL_FLOAT : GL_UNSIGNED_BYTE, pixels);
    err = glGetError();
    if (err != GL_NO_ERROR) {
        free(pixels);
        return gbl_dump_say_(
            c, GBL_DUMP_GL_ERROR, "gbl_dump: glReadPixels of %s raised %s%s", a->stem, gbl_dump_gl_error_name_(err),
            err == GL_INVALID_OPERATION ? " (a multisampled framebuffer? resolve it with glBlitFramebuffer first)"
                                        : "");
    }
    if (!gbl_dump_path_(path, sizeof path, dir, a->stem, ext)) {
        free(pixels);
        return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT, "gbl_dump: the folder name is too long");
    }
    rc = gbl_dump_write_file_(c, path, pixels, a->kind, width, height, a->channels, 0,
                              a->channels == 4 ? 3 : a->channels);
    if (rc == GBL_DUMP_OK && a->channels == 4) {
        char stem[300];
        snprintf(stem, sizeof stem, "%s_a", a->stem);
        if (!gbl_dump_path_(path, sizeof path, dir, stem, a->kind == 0 ? ".pfm" : ".pgm"))
            rc = gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT, "gbl_dump: the folder name is too long");
        else
            rc = gbl_dump_write_file_(c, path, pixels, a->kind, width, height, 4, 3, 1);
    }
    free(pixels);
    return rc;
}

/* The caller's read state, restored on every return. */
typedef struct gbl_dump_state_ {
    GLint read_framebuffer, pack_buffer, alignment, row_length, skip_rows, skip_pixels, swap_bytes;
} gbl_dump_state_;

static void gbl_dump_save_(gbl_dump_state_* s) {
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &s->read_framebuffer);
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &s->pack_buffer);
    glGetIntegerv(GL_PACK_ALIGNMENT, &s->alignment);
    glGetIntegerv(GL_PACK_ROW_LENGTH, &s->row_length);
    glGetIntegerv(GL_PACK_SKIP_ROWS, &s->skip_rows);
    glGetIntegerv(GL_PACK_SKIP_PIXELS, &s->skip_pixels);
    glGetIntegerv(GL_PACK_SWAP_BYTES, &s->swap_bytes);
    /* Tightly packed rows into client memory, so the buffers hold exactly width x height pixels. */
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
}

static void gbl_dump_restore_(const gbl_dump_state_* s) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, (GLuint)s->read_framebuffer);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, (GLuint)s->pack_buffer);
    glPixelStorei(GL_PACK_ALIGNMENT, s->alignment);
    glPixelStorei(GL_PACK_ROW_LENGTH, s->row_length);
    glPixelStorei(GL_PACK_SKIP_ROWS, s->skip_rows);
    glPixelStorei(GL_PACK_SKIP_PIXELS, s->skip_pixels);
    glPixelStorei(GL_PACK_SWAP_BYTES, s->swap_bytes);
}

static int gbl_dump_framebuffer_(gbl_dump_ctx_* c, GLuint framebuffer, int width, int height, const char* dir,
                                 const gbl_dump_options* o, gbl_dump_att_* att) {
    GLint read_buffer = GL_NONE, clamp = GL_FIXED_ONLY, max_color = 0;
    GLenum status, err;
    int i, rc = GBL_DUMP_OK;
    if (framebuffer == 0)
        return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT,
                             "gbl_dump: framebuffer 0 is the window's; pass the G-buffer's framebuffer object");
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    err = glGetError();
    if (err != GL_NO_ERROR)
        return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT,
                             "gbl_dump: framebuffer %u cannot be bound (%s): not a framebuffer name",
                             (unsigned)framebuffer, gbl_dump_gl_error_name_(err));
    status = glCheckFramebufferStatus(GL_READ_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        return gbl_dump_say_(c, GBL_DUMP_BAD_FRAMEBUFFER, "gbl_dump: framebuffer %u is incomplete (%s)",
                             (unsigned)framebuffer, gbl_dump_status_name_(status));
    glGetIntegerv(GL_MAX_COLOR_ATTACHMENTS, &max_color);
    if (o->color_count > max_color)
        return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT,
                             "gbl_dump: options.color_count %d is more than GL_MAX_COLOR_ATTACHMENTS %d",
                             o->color_count, (int)max_color);
    for (i = 0; i < o->color_count && rc == GBL_DUMP_OK; ++i)
        rc = gbl_dump_describe_(c, (GLenum)(GL_COLOR_ATTACHMENT0 + i), i, &att[i]);
    if (rc != GBL_DUMP_OK) return rc;
    if (o->depth) {
        GLint type = GL_NONE;
        glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                              GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
        if (type == GL_NONE)
            return gbl_dump_say_(c, GBL_DUMP_BAD_FRAMEBUFFER,
                                 "gbl_dump: framebuffer %u has no depth attachment (set options.depth to 0)",
                                 (unsigned)framebuffer);
    }
    for (i = 0; i < 6; ++i) {
        const int role[6] = {o->position, o->normal, o->albedo, o->specular, o->emissive, o->occlusion};
        static const char* const names[6] = {"position", "normal", "albedo", "specular", "emissive", "occlusion"};
        int need = i == 3   ? o->specular_channel + 1
                   : i == 5 ? o->occlusion_channel + 1
                   : (i == 1 && o->normal_encoding && strcmp(o->normal_encoding, "octahedral") == 0) ? 2
                                                                                                     : 3;
        if (role[i] >= 0 && att[role[i]].channels < need)
            return gbl_dump_say_(c, GBL_DUMP_BAD_ARGUMENT,
                                 "gbl_dump: options.%s is colour attachment %d, which has %d channel(s); it needs %d",
                                 names[i], role[i], att[role[i]].channels, need);
    }
    /* Float storage is read unclamped whatever the caller set (GL_FIXED_ONLY: the default). */
    glGetIntegerv(GL_CLAMP_READ_COLOR, &clamp);
    glClampColor(GL_CLAMP_READ_COLOR, GL_FIXED_ONLY);
    glGetIntegerv(GL_READ_BUFFER, &read_buffer);
    for (i = 0; i < o->color_count && rc == GBL_DUMP_OK; ++i) {
        glReadBuffer((GLenum)(GL_COLOR_ATTACHMENT0 + i));
        rc = gbl_dump_read_write_(c, dir, &att[i], 0, width, height);
    }
    if (rc == GBL_DUMP_OK && o->depth) {
        gbl_dump_att_ depth;
        memset(&depth, 0, sizeof depth);
        depth.channels = 1;
        depth.kind = 0;
        strcpy(depth.stem, "depth");
        rc = gbl_dump_read_write_(c, dir, &depth, 1, width, height);
    }
    glReadBuffer((GLenum)read_buffer);
    glClampColor(GL_CLAMP_READ_COLOR, (GLenum)clamp);
    return rc;
}

GBL_DUMP_DEF void gbl_dump_options_defaults(gbl_dump_options* o) {
    memset(o, 0, sizeof *o);
    o->color_count = 1;
    o->position = o->normal = o->albedo = o->specular = -1;
    o->emissive = o->occlusion = -1;
}

GBL_DUMP_DEF void gbl_dump_options_learnopengl(gbl_dump_options* o) {
    gbl_dump_options_defaults(o);
    o->color_count = 3;
    o->names[0] = "gPosition";
    o->names[1] = "gNormal";
    o->names[2] = "gAlbedoSpec";
    o->depth = 1;
    o->position = 0;
    o->normal = 1;
    o->albedo = 2;
    o->specular = 2;
    o->specular_channel = 3;
    o->shininess = 16.0f;
    o->shading = "learnopengl";
}

GBL_DUMP_DEF int gbl_dump(GLuint framebuffer, int width, int height, const char* dir, const gbl_dump_options* o,
                          char* message, size_t message_size) {
    gbl_dump_ctx_ c;
    gbl_dump_att_ att[GBL_DUMP_MAX_COLOR];
    gbl_dump_state_ state;
    GLenum pending;
    int i, rc, depth_listed = 0;
    c.message = message;
    c.message_size = message_size;
    if (message && message_size > 0) message[0] = '\0';
    if (!o) return gbl_dump_say_(&c, GBL_DUMP_BAD_ARGUMENT, "gbl_dump: options must not be NULL");
    rc = gbl_dump_check_options_(&c, o, width, height, dir);
    if (rc != GBL_DUMP_OK) return rc;
    memset(att, 0, sizeof att);
    for (i = 0; i < o->color_count; ++i) {
        if (o->names[i])
            snprintf(att[i].stem, sizeof att[i].stem, "%s", o->names[i]);
        else
            snprintf(att[i].stem, sizeof att[i].stem, "color%d", i);
    }
    /* An error raised before the call would be reported as the read's own. */
    pending = glGetError();
    if (pending != GL_NO_ERROR)
        return gbl_dump_say_(&c, GBL_DUMP_GL_ERROR,
                             "gbl_dump: %s was raised before gbl_dump was called (by the geometry pass or earlier); "
                             "nothing was read",
                             gbl_dump_gl_error_name_(pending));
    gbl_dump_save_(&state);
    rc = gbl_dump_framebuffer_(&c, framebuffer, width, height, dir, o, att);
    gbl_dump_restore_(&state);
    if (rc != GBL_DUMP_OK) return rc;
    rc = gbl_dump_write_manifest_(&c, dir, o, att, &depth_listed);
    if (rc != GBL_DUMP_OK) return rc;
    gbl_dump_say_(
        &c, GBL_DUMP_OK, "gbl_dump: wrote %d attachment(s)%s and manifest.json to %s%s", o->color_count,
        o->depth ? " and depth" : "", dir,
        o->depth && !depth_listed ? " (depth.pfm is not in the manifest: pass the camera for its near and far)" : "");
    return GBL_DUMP_OK;
}

#endif /* GBL_DUMP_IMPLEMENTATION_DONE */
#endif /* GBL_DUMP_IMPLEMENTATION */
