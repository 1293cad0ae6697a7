// A small deferred renderer written as a reader of LearnOpenGL's deferred chapter would: the program
// `gbuffer-lab capture` is tested on. It shares no code with gbuffer-lab (EGL, epoxy and GLM only).
//
//   deferred_demo [--size WxH] [--frames N] [--out LIT.pfm] [--variant 1..5]
//
// Each frame: a geometry pass into a G-buffer (position and normal RGBA16F, albedo + specular RGBA8,
// depth), a full-screen lighting pass over four point lights into the default framebuffer (a pbuffer),
// eglSwapBuffers. After the last frame the lit image is read back and written as a PFM (rows bottom-up,
// as PFM and glReadPixels both have them). Variant 2 names its samplers and uniforms otherwise
// (uPositionTex, uNormalTex, uAlbedoTex, uLightPos[], uLightColor[], uEye, one viewProj). Two more
// are broken on purpose, for capture's refusals: 3 draws into one target only (no G-buffer, as a forward
// renderer), 4 binds none of the G-buffer's textures for its lighting pass. Variant 5 is variant 1 with its
// camera hidden in one matrix whose name says nothing (uTransform), which capture must solve from the positions.
#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

// ---------------------------------------------------------------- shaders of the two variants
char const* const kGeometryVs1 = R"(#version 330 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
out vec3 FragPos;
out vec3 Normal;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
void main() {
    vec4 worldPos = model * vec4(aPos, 1.0);
    FragPos = worldPos.xyz;
    Normal = transpose(inverse(mat3(model))) * aNormal;
    gl_Position = projection * view * worldPos;
})";
char const* const kGeometryVs2 = R"(#version 330 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
out vec3 FragPos;
out vec3 Normal;
uniform mat4 uModel;
uniform mat4 viewProj;
void main() {
    vec4 worldPos = uModel * vec4(aPos, 1.0);
    FragPos = worldPos.xyz;
    Normal = transpose(inverse(mat3(uModel))) * aNormal;
    gl_Position = viewProj * worldPos;
})";
char const* const kGeometryVs5 = R"(#version 330 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
out vec3 FragPos;
out vec3 Normal;
uniform mat4 model;
uniform mat4 uTransform;
void main() {
    vec4 worldPos = model * vec4(aPos, 1.0);
    FragPos = worldPos.xyz;
    Normal = transpose(inverse(mat3(model))) * aNormal;
    gl_Position = uTransform * worldPos;
})";
char const* const kGeometryFs = R"(#version 330 core
layout(location = 0) out vec4 gPosition;
layout(location = 1) out vec4 gNormal;
layout(location = 2) out vec4 gAlbedoSpec;
in vec3 FragPos;
in vec3 Normal;
uniform vec4 materialColor;
void main() {
    gPosition = vec4(FragPos, 1.0);
    gNormal = vec4(normalize(Normal), 1.0);
    gAlbedoSpec = materialColor;
})";
char const* const kQuadVs = R"(#version 330 core
out vec2 TexCoords;
void main() {
    vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
    TexCoords = p * 0.5 + 0.5;
    gl_Position = vec4(p, 0.0, 1.0);
})";
// LearnOpenGL's deferred lighting equation: ambient 0.1, exponent 16, 1 / (1 + l d + q d^2).
char const* const kLightingFs1 = R"(#version 330 core
out vec4 FragColor;
in vec2 TexCoords;
uniform sampler2D gPosition;
uniform sampler2D gNormal;
uniform sampler2D gAlbedoSpec;
struct Light { vec3 Position; vec3 Color; float Linear; float Quadratic; };
const int NR_LIGHTS = 4;
uniform Light lights[NR_LIGHTS];
uniform vec3 viewPos;
void main() {
    vec3 FragPos = texture(gPosition, TexCoords).rgb;
    vec3 Normal = texture(gNormal, TexCoords).rgb;
    vec3 Diffuse = texture(gAlbedoSpec, TexCoords).rgb;
    float Specular = texture(gAlbedoSpec, TexCoords).a;
    vec3 lighting = Diffuse * 0.1;
    vec3 viewDir = normalize(viewPos - FragPos);
    for (int i = 0; i < NR_LIGHTS; ++i) {
        vec3 lightDir = normalize(lights[i].Position - FragPos);
        vec3 diffuse = max(dot(Normal, lightDir), 0.0) * Diffuse * lights[i].Color;
        vec3 halfwayDir = normalize(lightDir + viewDir);
        float spec = pow(max(dot(Normal, halfwayDir), 0.0), 16.0);
        vec3 specular = lights[i].Color * spec * Specular;
        float distance = length(lights[i].Position - FragPos);
        float attenuation = 1.0 / (1.0 + lights[i].Linear * distance + lights[i].Quadratic * distance * distance);
        lighting += (diffuse + specular) * attenuation;
    }
    FragColor = vec4(lighting, 1.0);
})";
char const* const kLightingFs2 = R"(#version 330 core
out vec4 FragColor;
in vec2 TexCoords;
uniform sampler2D uPositionTex;
uniform sampler2D uNormalTex;
uniform sampler2D uAlbedoTex;
uniform vec3 uLightPos[4];
uniform vec3 uLightColor[4];
uniform vec3 uEye;
void main() {
    vec3 p = texture(uPositionTex, TexCoords).rgb;
    vec3 n = texture(uNormalTex, TexCoords).rgb;
    vec4 a = texture(uAlbedoTex, TexCoords);
    vec3 c = a.rgb * 0.1;
    vec3 v = normalize(uEye - p);
    for (int i = 0; i < 4; ++i) {
        vec3 l = normalize(uLightPos[i] - p);
        float d = length(uLightPos[i] - p);
        float att = 1.0 / (1.0 + 0.22 * d + 0.20 * d * d);
        float s = pow(max(dot(n, normalize(l + v)), 0.0), 16.0);
        c += (max(dot(n, l), 0.0) * a.rgb + s * a.a) * uLightColor[i] * att;
    }
    FragColor = vec4(c, 1.0);
})";

// ---------------------------------------------------------------- the scene
struct Light {
    glm::vec3 position, color;
};
Light const kLights[4] = {{{-2.0f, 1.5f, 1.5f}, {1.0f, 0.6f, 0.3f}},
                          {{2.0f, 2.0f, 0.5f}, {0.3f, 0.6f, 1.0f}},
                          {{0.0f, 1.0f, -2.5f}, {0.8f, 0.8f, 0.8f}},
                          {{0.5f, 3.0f, 2.5f}, {0.5f, 1.0f, 0.4f}}};
float const kLinear = 0.22f, kQuadratic = 0.20f;
struct Box {
    glm::vec3 centre, half;
    float yaw;
    glm::vec4 color;  // albedo rgb, specular a
};
Box const kBoxes[4] = {{{0.0f, -0.05f, 0.0f}, {4.0f, 0.05f, 4.0f}, 0.0f, {0.45f, 0.45f, 0.4f, 0.2f}},
                       {{-1.2f, 0.5f, 0.0f}, {0.5f, 0.5f, 0.5f}, 0.4f, {0.8f, 0.2f, 0.2f, 0.8f}},
                       {{1.0f, 0.75f, -0.6f}, {0.4f, 0.75f, 0.4f}, -0.3f, {0.2f, 0.7f, 0.3f, 0.5f}},
                       {{0.3f, 0.3f, 1.3f}, {0.3f, 0.3f, 0.3f}, 1.0f, {0.3f, 0.4f, 0.9f, 1.0f}}};
glm::vec3 const kEye(1.5f, 3.2f, 5.5f), kTarget(0.0f, 0.3f, 0.0f);

// A unit cube, [-1, 1]^3: six faces of two triangles, position and normal interleaved.
std::vector<float> cubeVertices() {
    std::vector<float> v;
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {-1.0f, 1.0f}) {
            glm::vec3 n(0.0f), a(0.0f), b(0.0f);
            n[axis] = sign;
            a[(axis + 1) % 3] = 1.0f;
            b[(axis + 2) % 3] = sign;  // keeps the triangles counter-clockwise seen from outside
            glm::vec3 const c[4] = {n - a - b, n + a - b, n + a + b, n - a + b};
            for (int i : {0, 1, 2, 0, 2, 3}) v.insert(v.end(), {c[i].x, c[i].y, c[i].z, n.x, n.y, n.z});
        }
    return v;
}

GLuint shader(GLenum stage, char const* source) {
    GLuint s = glCreateShader(stage);
    glShaderSource(s, 1, &source, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048];
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        std::fprintf(stderr, "deferred_demo: shader compile failed: %s\n", log);
        std::exit(1);
    }
    return s;
}
GLuint program(char const* vs, char const* fs) {
    GLuint p = glCreateProgram();
    glAttachShader(p, shader(GL_VERTEX_SHADER, vs));
    glAttachShader(p, shader(GL_FRAGMENT_SHADER, fs));
    glLinkProgram(p);
    return p;
}
GLuint target(GLenum internal, GLenum format, GLenum type, int w, int h, GLenum attachment) {
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal), w, h, 0, format, type, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, t, 0);
    return t;
}

}  // namespace

int main(int argc, char** argv) {
    int w = 320, h = 240, frames = 3, variant = 1;
    char const* out = nullptr;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--size")) std::sscanf(argv[i + 1], "%dx%d", &w, &h);
        if (!std::strcmp(argv[i], "--frames")) frames = std::atoi(argv[i + 1]);
        if (!std::strcmp(argv[i], "--variant")) variant = std::atoi(argv[i + 1]);
        if (!std::strcmp(argv[i], "--out")) out = argv[i + 1];
    }
    EGLDisplay dpy = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, nullptr, nullptr) || !eglBindAPI(EGL_OPENGL_API)) {
        std::fprintf(stderr, "deferred_demo: no EGL display\n");
        return 1;
    }
    EGLint const configAttribs[] = {EGL_SURFACE_TYPE,
                                    EGL_PBUFFER_BIT,
                                    EGL_RENDERABLE_TYPE,
                                    EGL_OPENGL_BIT,
                                    EGL_RED_SIZE,
                                    8,
                                    EGL_GREEN_SIZE,
                                    8,
                                    EGL_BLUE_SIZE,
                                    8,
                                    EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    eglChooseConfig(dpy, configAttribs, &config, 1, &count);
    EGLint const ctxAttribs[] = {
        EGL_CONTEXT_MAJOR_VERSION,           3,       EGL_CONTEXT_MINOR_VERSION, 3, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLint const surfAttribs[] = {EGL_WIDTH, w, EGL_HEIGHT, h, EGL_NONE};
    EGLContext ctx = count ? eglCreateContext(dpy, config, EGL_NO_CONTEXT, ctxAttribs) : EGL_NO_CONTEXT;
    EGLSurface surf = count ? eglCreatePbufferSurface(dpy, config, surfAttribs) : EGL_NO_SURFACE;
    if (ctx == EGL_NO_CONTEXT || surf == EGL_NO_SURFACE || !eglMakeCurrent(dpy, surf, surf, ctx)) {
        std::fprintf(stderr, "deferred_demo: no OpenGL 3.3 context on a %dx%d pbuffer\n", w, h);
        return 1;
    }

    GLuint const geometry = program(variant == 2   ? kGeometryVs2
                                    : variant == 5 ? kGeometryVs5
                                                   : kGeometryVs1,
                                    kGeometryFs);
    GLuint const lighting = program(kQuadVs, variant == 2 ? kLightingFs2 : kLightingFs1);
    std::vector<float> const cube = cubeVertices();
    GLuint vao = 0, vbo = 0, quadVao = 0;
    glGenVertexArrays(1, &vao);
    glGenVertexArrays(1, &quadVao);
    glGenBuffers(1, &vbo);
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(cube.size() * sizeof(float)), cube.data(), GL_STATIC_DRAW);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);

    GLuint gBuffer = 0, depth = 0;
    glGenFramebuffers(1, &gBuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, gBuffer);
    GLuint const gPosition = target(GL_RGBA16F, GL_RGBA, GL_FLOAT, w, h, GL_COLOR_ATTACHMENT0);
    GLuint const gNormal = target(GL_RGBA16F, GL_RGBA, GL_FLOAT, w, h, GL_COLOR_ATTACHMENT1);
    GLuint const gAlbedoSpec = target(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, w, h, GL_COLOR_ATTACHMENT2);
    GLenum const buffers[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    glDrawBuffers(variant == 3 ? 1 : 3, buffers);
    glGenRenderbuffers(1, &depth);
    glBindRenderbuffer(GL_RENDERBUFFER, depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, w, h);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        std::fprintf(stderr, "deferred_demo: G-buffer incomplete\n");
        return 1;
    }

    glm::mat4 const view = glm::lookAt(kEye, kTarget, glm::vec3(0, 1, 0));
    glm::mat4 const projection = glm::perspective(glm::radians(45.0f), float(w) / float(h), 0.1f, 50.0f);
    bool const v2 = variant == 2;
    glUseProgram(lighting);
    glUniform1i(glGetUniformLocation(lighting, v2 ? "uPositionTex" : "gPosition"), 0);
    glUniform1i(glGetUniformLocation(lighting, v2 ? "uNormalTex" : "gNormal"), 1);
    glUniform1i(glGetUniformLocation(lighting, v2 ? "uAlbedoTex" : "gAlbedoSpec"), 2);

    for (int frame = 0; frame < frames; ++frame) {
        // Geometry pass.
        glBindFramebuffer(GL_FRAMEBUFFER, gBuffer);
        glViewport(0, 0, w, h);
        glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glEnable(GL_DEPTH_TEST);
        glUseProgram(geometry);
        if (v2 || variant == 5) {
            glm::mat4 const vp = projection * view;
            glUniformMatrix4fv(glGetUniformLocation(geometry, v2 ? "viewProj" : "uTransform"), 1, GL_FALSE,
                               glm::value_ptr(vp));
        } else {
            glUniformMatrix4fv(glGetUniformLocation(geometry, "view"), 1, GL_FALSE, glm::value_ptr(view));
            glUniformMatrix4fv(glGetUniformLocation(geometry, "projection"), 1, GL_FALSE, glm::value_ptr(projection));
        }
        glBindVertexArray(vao);
        for (Box const& b : kBoxes) {
            glm::mat4 model = glm::translate(glm::mat4(1.0f), b.centre);
            model = glm::scale(glm::rotate(model, b.yaw, glm::vec3(0, 1, 0)), b.half);
            glUniformMatrix4fv(glGetUniformLocation(geometry, v2 ? "uModel" : "model"), 1, GL_FALSE,
                               glm::value_ptr(model));
            glUniform4fv(glGetUniformLocation(geometry, "materialColor"), 1, glm::value_ptr(b.color));
            glDrawArrays(GL_TRIANGLES, 0, 36);
        }
        // Lighting pass into the default framebuffer.
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDisable(GL_DEPTH_TEST);
        glClear(GL_COLOR_BUFFER_BIT);
        glUseProgram(lighting);
        GLuint const sampled[3] = {gPosition, gNormal, gAlbedoSpec};
        for (int unit = 0; unit < 3; ++unit) {
            glActiveTexture(GLenum(GL_TEXTURE0 + unit));
            glBindTexture(GL_TEXTURE_2D, variant == 4 ? 0 : sampled[unit]);
        }
        for (int i = 0; i < 4; ++i) {
            std::string const at = "[" + std::to_string(i) + "]";
            glm::vec3 const p = kLights[i].position, c = kLights[i].color;
            if (v2) {
                glUniform3fv(glGetUniformLocation(lighting, ("uLightPos" + at).c_str()), 1, glm::value_ptr(p));
                glUniform3fv(glGetUniformLocation(lighting, ("uLightColor" + at).c_str()), 1, glm::value_ptr(c));
                continue;
            }
            std::string const l = "lights" + at + ".";
            glUniform3fv(glGetUniformLocation(lighting, (l + "Position").c_str()), 1, glm::value_ptr(p));
            glUniform3fv(glGetUniformLocation(lighting, (l + "Color").c_str()), 1, glm::value_ptr(c));
            glUniform1f(glGetUniformLocation(lighting, (l + "Linear").c_str()), kLinear);
            glUniform1f(glGetUniformLocation(lighting, (l + "Quadratic").c_str()), kQuadratic);
        }
        glUniform3fv(glGetUniformLocation(lighting, v2 ? "uEye" : "viewPos"), 1, glm::value_ptr(kEye));
        glBindVertexArray(quadVao);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        if (frame + 1 == frames && out) {
            std::vector<float> lit(std::size_t(w) * std::size_t(h) * 3);
            glReadPixels(0, 0, w, h, GL_RGB, GL_FLOAT, lit.data());
            std::FILE* f = std::fopen(out, "wb");
            if (!f) return 1;
            std::fprintf(f, "PF\n%d %d\n-1.0\n", w, h);
            std::fwrite(lit.data(), sizeof(float), lit.size(), f);
            std::fclose(f);
        }
        eglSwapBuffers(dpy, surf);
    }
    eglTerminate(dpy);
    return glGetError() == GL_NO_ERROR ? 0 : 1;
}
