// tools/gbl_dump/gbl_dump.h on a G-buffer of the test's own: a LearnOpenGL-style frame (a floor and a
// wall, seen from above one side, the sky above them) is rendered into an FBO, dumped by the header
// compiled as C++ here and as C in gbl_dump_c.c, and opened with the importer: the values the GL holds
// come back at the same pixels, match the scene's analytic values, and `check` finds nothing.
#include "core/light_math.h"
#include "gl/framebuffer.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"
#include "gl_fixture.h"
#include "import/gbuffer_checks.h"
#include "import/gbuffer_manifest.h"
#include "import/imported_gbuffer.h"
#include "import/relight_frame.h"
#include "renderer.h"
#include "run_command.h"

#define GBL_DUMP_STATIC
#define GBL_DUMP_IMPLEMENTATION
#include "gbl_dump.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

extern "C" int gbl_dump_test_from_c(GLuint framebuffer, int width, int height, char const* dir, float const eye[3],
                                    float const target[3], float fov_y_degrees, float near_plane, float far_plane,
                                    char* message, size_t message_size);

using namespace gbl;

namespace {

// Wider than high and looked at from one side, so a frame turned over or mirrored puts the sky where
// the floor was and moves every position.
constexpr int kW = 96, kH = 64;
glm::vec3 const kEye(1.5f, 3.0f, 5.0f), kTarget(0.0f, 0.5f, -2.0f);
constexpr float kFov = 50.0f, kNear = 0.1f, kFar = 50.0f;

// A parallelogram origin + s u + t v (s, t in [0, 1]) with one normal, blue albedo and specular.
struct Quad {
    glm::vec3 origin, u, v, normal;
    float albedoB, specular;
};
std::array<Quad, 2> const kQuads{{
    {{-4, 0, 3}, {8, 0, 0}, {0, 0, -11}, {0, 1, 0}, 0.2f, 0.3f},  // the floor: x in [-4, 4], z in [-8, 3]
    {{-3, 0, -6}, {6, 0, 0}, {0, 2, 0}, {0, 0, 1}, 0.4f, 0.75f},  // a wall at z = -6 facing +z
}};

// Albedo varies across the world (in [0.1, 0.54], under the sRGB heuristic's median of 0.5).
glm::vec3 albedoAt(glm::vec3 p, Quad const& q) {
    return {0.1f + 0.05f * (p.x + 4.0f), 0.1f + 0.04f * (3.0f - p.z), q.albedoB};
}

char const* const kVertex = R"(#version 330 core
uniform mat4 view;
uniform mat4 projection;
uniform vec3 origin[2];
uniform vec3 u[2];
uniform vec3 v[2];
uniform vec3 normal[2];
uniform float albedoB[2];
uniform float specular[2];
out vec3 FragPos;
out vec3 Normal;
flat out vec2 Material;
void main() {
    int q = gl_VertexID / 6;
    int k = gl_VertexID % 6;
    vec2 st = vec2(k == 1 || k == 2 || k == 4 ? 1.0 : 0.0, k == 2 || k == 4 || k == 5 ? 1.0 : 0.0);
    FragPos = origin[q] + st.x * u[q] + st.y * v[q];
    Normal = normal[q];
    Material = vec2(albedoB[q], specular[q]);
    gl_Position = projection * view * vec4(FragPos, 1.0);
})";

// As LearnOpenGL's g_buffer.fs writes its three targets.
char const* const kFragment = R"(#version 330 core
layout(location = 0) out vec3 gPosition;
layout(location = 1) out vec3 gNormal;
layout(location = 2) out vec4 gAlbedoSpec;
in vec3 FragPos;
in vec3 Normal;
flat in vec2 Material;
void main() {
    gPosition = FragPos;
    gNormal = normalize(Normal);
    gAlbedoSpec = vec4(0.1 + 0.05 * (FragPos.x + 4.0), 0.1 + 0.04 * (3.0 - FragPos.z), Material.x, Material.y);
})";

glm::mat4 viewMatrix() {
    return glm::lookAt(kEye, kTarget, glm::vec3(0, 1, 0));
}
glm::mat4 projectionMatrix() {
    return glm::perspective(glm::radians(kFov), float(kW) / float(kH), kNear, kFar);
}

struct Hit {
    int quad;
    glm::vec3 p;
};

// The nearest quad behind a point of the frame (pixels from the top-left corner), by ray casting.
std::optional<Hit> castRay(glm::mat4 const& inverseViewProjection, float px, float py) {
    glm::vec2 const ndc(px / float(kW) * 2.0f - 1.0f, 1.0f - py / float(kH) * 2.0f);
    glm::vec4 const n = inverseViewProjection * glm::vec4(ndc, -1.0f, 1.0f);
    glm::vec4 const f = inverseViewProjection * glm::vec4(ndc, 1.0f, 1.0f);
    glm::vec3 const a = glm::vec3(n) / n.w, d = glm::vec3(f) / f.w - a;
    std::optional<Hit> best;
    float bestT = 0.0f;
    for (int i = 0; i < int(kQuads.size()); ++i) {
        Quad const& q = kQuads[std::size_t(i)];
        float const t = glm::dot(q.normal, q.origin - a) / glm::dot(q.normal, d);
        glm::vec3 const p = a + t * d, r = p - q.origin;
        float const s = glm::dot(r, q.u) / glm::dot(q.u, q.u), w = glm::dot(r, q.v) / glm::dot(q.v, q.v);
        if (t > 0.0f && s >= 0.0f && s <= 1.0f && w >= 0.0f && w <= 1.0f && (!best || t < bestT)) {
            best = Hit{i, p};
            bestT = t;
        }
    }
    return best;
}

// The centre's hit when the whole pixel sees the same quad (or the sky): edges are left out, where
// rasterisation and the ray at the centre may disagree about coverage.
std::optional<std::optional<Hit>> interiorHit(glm::mat4 const& ivp, int x, int y) {
    auto const centre = castRay(ivp, float(x) + 0.5f, float(y) + 0.5f);
    for (float dx : {0.05f, 0.95f})
        for (float dy : {0.05f, 0.95f}) {
            auto const h = castRay(ivp, float(x) + dx, float(y) + dy);
            if (bool(h) != bool(centre) || (h && h->quad != centre->quad)) return std::nullopt;
        }
    return centre;
}

std::string fileBytes(std::string const& path) {
    std::ifstream f(path, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

// What the GL holds, rows bottom-up as glReadPixels returns them.
struct GlReadBack {
    std::vector<float> position, normal, depth;
    std::vector<std::uint8_t> albedoSpec;
};

class GbufferDumpGlTest : public test::GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        position_ = gl::Texture::create2D(GL_RGB16F, kW, kH, "dump test gPosition");
        normal_ = gl::Texture::create2D(GL_RGB16F, kW, kH, "dump test gNormal");
        albedoSpec_ = gl::Texture::create2D(GL_RGBA8, kW, kH, "dump test gAlbedoSpec");
        depth_ = gl::Texture::create2D(GL_DEPTH24_STENCIL8, kW, kH, "dump test depth");  // 24-bit depth, as LearnOpenGL
        gBuffer_ = gl::Framebuffer::create({&position_, &normal_, &albedoSpec_}, &depth_, "dump test gBuffer");
        ASSERT_FALSE(gBuffer_.error()) << *gBuffer_.error();
        std::string log;
        auto program = gl::Program::build(
            {{GL_VERTEX_SHADER, "dump_test.vs", kVertex}, {GL_FRAGMENT_SHADER, "dump_test.fs", kFragment}},
            "dump test geometry", &log);
        ASSERT_TRUE(program) << log;
        program_ = std::move(*program);
        vao_ = gl::VertexArray::create("dump test quads");
    }

    // The geometry pass: cleared to zero (LearnOpenGL's black clear; depth 1), then the two quads.
    void renderGeometry() {
        glBindFramebuffer(GL_FRAMEBUFFER, gBuffer_.id());
        glViewport(0, 0, kW, kH);
        glDisable(GL_BLEND);
        glDisable(GL_CULL_FACE);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_TRUE);
        glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
        glClearDepth(1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        program_.use();
        program_.set("view", viewMatrix());
        program_.set("projection", projectionMatrix());
        for (int i = 0; i < 2; ++i) {
            std::string const at = "[" + std::to_string(i) + "]";
            Quad const& q = kQuads[std::size_t(i)];
            program_.set("origin" + at, q.origin);
            program_.set("u" + at, q.u);
            program_.set("v" + at, q.v);
            program_.set("normal" + at, q.normal);
            program_.set("albedoB" + at, q.albedoB);
            program_.set("specular" + at, q.specular);
        }
        glBindVertexArray(vao_.id());
        glDrawArrays(GL_TRIANGLES, 0, 12);
        glBindVertexArray(0);
        glDisable(GL_DEPTH_TEST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }

    GlReadBack readBack() const {
        GlReadBack r;
        std::size_t const n = std::size_t(kW) * std::size_t(kH);
        r.position.resize(n * 3);
        r.normal.resize(n * 3);
        r.albedoSpec.resize(n * 4);
        r.depth.resize(n);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, gBuffer_.id());
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadBuffer(GL_COLOR_ATTACHMENT0);
        glReadPixels(0, 0, kW, kH, GL_RGB, GL_FLOAT, r.position.data());
        glReadBuffer(GL_COLOR_ATTACHMENT1);
        glReadPixels(0, 0, kW, kH, GL_RGB, GL_FLOAT, r.normal.data());
        glReadBuffer(GL_COLOR_ATTACHMENT2);
        glReadPixels(0, 0, kW, kH, GL_RGBA, GL_UNSIGNED_BYTE, r.albedoSpec.data());
        glReadPixels(0, 0, kW, kH, GL_DEPTH_COMPONENT, GL_FLOAT, r.depth.data());
        glReadBuffer(GL_COLOR_ATTACHMENT0);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        return r;
    }

    gl::Texture position_, normal_, albedoSpec_, depth_;
    gl::Framebuffer gBuffer_;
    gl::Program program_;
    gl::VertexArray vao_;
};

ImportedGBuffer open(std::string const& dir) {
    ManifestLoad m = loadManifest(dir);
    EXPECT_TRUE(m.manifest) << m.error;
    if (!m.manifest) return {};
    GBufferLoad g = loadGBuffer(*m.manifest);
    EXPECT_TRUE(g.gbuffer) << g.error;
    return g.gbuffer ? std::move(*g.gbuffer) : ImportedGBuffer{};
}

// Every pixel of the files holds what the GL held at the same place: row y of the import (top down)
// is row kH - 1 - y of glReadPixels (bottom up). Exact: PFM keeps the floats, PPM the bytes.
void expectSameAsGl(ImportedGBuffer const& g, GlReadBack const& gl) {
    ASSERT_EQ(g.width, kW);
    ASSERT_EQ(g.height, kH);
    ImportedImage const* pos = g.image("position");
    ImportedImage const* nrm = g.image("normal");
    ImportedImage const* alb = g.image("albedo");
    ImportedImage const* spec = g.image("specular");
    ImportedImage const* dep = g.image("depth");
    ASSERT_TRUE(pos && nrm && alb && spec && dep);
    EXPECT_EQ(pos->storage, SampleStorage::Float);
    EXPECT_EQ(alb->storage, SampleStorage::Uint8);
    int mismatches = 0;
    std::string first;
    auto same = [&](bool ok, char const* what, int x, int y) {
        if (ok) return;
        if (mismatches++ == 0) first = std::string(what) + " at " + std::to_string(x) + "," + std::to_string(y);
    };
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            std::size_t const p = std::size_t(y) * kW + std::size_t(x);
            std::size_t const q = std::size_t(kH - 1 - y) * kW + std::size_t(x);
            for (int c = 0; c < 3; ++c) {
                same(pos->at(p, c) == gl.position[q * 3 + std::size_t(c)], "position", x, y);
                same(nrm->at(p, c) == gl.normal[q * 3 + std::size_t(c)], "normal", x, y);
                same(std::lround(alb->at(p, c) * 255.0f) == gl.albedoSpec[q * 4 + std::size_t(c)], "albedo", x, y);
            }
            same(std::lround(spec->at(p, 0) * 255.0f) == gl.albedoSpec[q * 4 + 3], "specular", x, y);
            same(dep->at(p, 0) == gl.depth[q], "depth", x, y);
        }
    EXPECT_EQ(mismatches, 0) << "first: " << first;
}

// The import against the scene itself: positions, normals, albedo, specular and view distance where
// a pixel sees one quad, background where it sees the sky.
void expectSceneValues(ImportedGBuffer const& g) {
    glm::mat4 const view = viewMatrix();
    glm::mat4 const ivp = glm::inverse(projectionMatrix() * view);
    ASSERT_EQ(g.position.size(), std::size_t(kW) * kH);
    ASSERT_EQ(g.viewDistance.size(), std::size_t(kW) * kH);
    int geometry = 0, sky = 0, bad = 0;
    std::string first;
    auto expect = [&](bool ok, std::string const& what) {
        if (!ok && bad++ == 0) first = what;
    };
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            auto const h = interiorHit(ivp, x, y);
            if (!h) continue;
            std::size_t const p = std::size_t(y) * kW + std::size_t(x);
            std::string const at = " at " + std::to_string(x) + "," + std::to_string(y);
            if (!*h) {
                ++sky;
                expect(g.background[p] == 1, "background" + at);
                continue;
            }
            ++geometry;
            Quad const& q = kQuads[std::size_t((*h)->quad)];
            glm::vec3 const e = (*h)->p;
            expect(g.background[p] == 0, "geometry" + at);
            // RGB16F holds 11 significant bits: at |p| < 11 a step of at most 2^-7 (0.008); the GL
            // interpolates in float, which moves the point by far less.
            expect(glm::length(g.position[p] - e) < 0.01f, "position" + at);
            // (0, 1, 0) and (0, 0, 1) are exact in half floats; normalize() may round by an ulp.
            expect(glm::length(g.normal[p] - q.normal) < 1e-3f, "normal" + at);
            // 8-bit albedo: half a level of rounding, plus the position's effect on the gradient (0.05
            // per unit times 0.01 units at most).
            glm::vec3 const a = albedoAt(e, q);
            expect(glm::length(g.albedo[p] - a) < 1.5f / 255.0f, "albedo" + at);
            expect(std::abs(g.specular[p] - q.specular) < 0.5f / 255.0f, "specular" + at);
            // 24-bit window depth read as float: at 11 units and near 0.1 a step of depth moves the
            // distance by about d^2 / near * 2^-24 (7e-5); 1e-3 of the distance leaves room for that.
            float const d = -(view * glm::vec4(e, 1.0f)).z;
            expect(std::abs(g.viewDistance[p] - d) < 1e-3f * d, "view distance" + at);
        }
    EXPECT_EQ(bad, 0) << bad << " pixels differ from the scene; first: " << first;
    // The frame has both, in the expected places: sky along the top row, floor along the bottom.
    EXPECT_GT(geometry, kW * kH / 3);
    EXPECT_GT(sky, kW * 4);
    for (int x = 0; x < kW; ++x) {
        EXPECT_EQ(g.background[std::size_t(x)], 1) << "top row, x " << x;
        EXPECT_EQ(g.background[std::size_t(kH - 1) * kW + std::size_t(x)], 0) << "bottom row, x " << x;
    }
}

std::array<float, 6> const kLightPositions{0.0f, 1.0f, 2.0f, -2.0f, 0.5f, -4.0f};
std::array<float, 6> const kLightColors{1.0f, 0.5f, 0.2f, 0.1f, 0.3f, 0.9f};
std::array<float, 2> const kLinear{0.7f, 0.35f};

// The dump options a LearnOpenGL reader passes: the learnopengl preset, the camera's matrices and
// the two lights above (the options point into this object, so it outlives the gbl_dump call).
struct LearnOpenGlDump {
    LearnOpenGlDump(glm::mat4 const& view, glm::mat4 const& projection) {
        gbl_dump_options_learnopengl(&options);
        camera.view = glm::value_ptr(view);
        camera.projection = glm::value_ptr(projection);
        lights.count = 2;
        lights.positions = kLightPositions.data();
        lights.colors = kLightColors.data();
        lights.linear_each = kLinear.data();
        lights.quadratic = 1.8f;
        options.camera = &camera;
        options.lights = &lights;
    }
    LearnOpenGlDump(LearnOpenGlDump const&) = delete;
    LearnOpenGlDump& operator=(LearnOpenGlDump const&) = delete;
    gbl_dump_options options;
    gbl_dump_camera camera{};
    gbl_dump_lights lights{};
};

}  // namespace

TEST_F(GbufferDumpGlTest, DumpOpensWithTheGlValuesAndNoFinding) {
    renderGeometry();
    GlReadBack const gl = readBack();
    glm::mat4 const view = viewMatrix(), projection = projectionMatrix();

    LearnOpenGlDump dump(view, projection);
    gbl_dump_options& o = dump.options;

    // The caller's read state, which the dump must leave as it found it.
    GLuint other = 0;
    glGenFramebuffers(1, &other);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, other);
    glPixelStorei(GL_PACK_ALIGNMENT, 2);

    std::string const dir = test::freshTempDir("gbl_dump_cpp");
    char message[1024];
    ASSERT_EQ(gbl_dump(gBuffer_.id(), kW, kH, dir.c_str(), &o, message, sizeof message), GBL_DUMP_OK) << message;
    EXPECT_NE(std::string(message).find("wrote 3 attachment(s) and depth"), std::string::npos) << message;

    GLint readBinding = 0, alignment = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readBinding);
    glGetIntegerv(GL_PACK_ALIGNMENT, &alignment);
    EXPECT_EQ(GLuint(readBinding), other);
    EXPECT_EQ(alignment, 2);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glDeleteFramebuffers(1, &other);

    ImportedGBuffer const g = open(dir);
    expectSameAsGl(g, gl);
    expectSceneValues(g);
    GBufferCheckReport const report = checkGBuffer(g);
    for (auto const& f : report.findings) ADD_FAILURE() << f.check << " (" << f.attachment << "): " << f.cause;

    // The manifest carries the camera (column-major matrices read back as given) and the lights.
    ASSERT_TRUE(g.camera);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            EXPECT_EQ(g.camera->view[c][r], view[c][r]) << c << "," << r;
            EXPECT_EQ(g.camera->projection[c][r], projection[c][r]) << c << "," << r;
        }
    ASSERT_EQ(g.manifest.lights.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        PointLight const& l = g.manifest.lights[i];
        EXPECT_EQ(l.position, glm::make_vec3(kLightPositions.data() + 3 * i));
        EXPECT_EQ(l.color, glm::make_vec3(kLightColors.data() + 3 * i));
        EXPECT_EQ(l.kc, 1.0f);
        EXPECT_EQ(l.kl, kLinear[i]);
        EXPECT_EQ(l.kq, 1.8f);
    }
    EXPECT_EQ(g.manifest.shininess, 16.0f);
    EXPECT_EQ(g.manifest.shading, ShadingModel::LearnOpenGl);

    // The command a reader runs on the folder.
    auto const c = test::runGbufferLab({"check", dir, "--json"});
    EXPECT_EQ(c.exitCode, 0) << c.output;
    EXPECT_NE(c.output.find("\"findings\": []"), std::string::npos) << c.output;

    // The header compiled as C, with the camera given by placement and lens: the same files, and a
    // manifest whose camera the importer builds into the same projection for this frame's size.
    std::string const cdir = test::freshTempDir("gbl_dump_c");
    float const eye[3] = {kEye.x, kEye.y, kEye.z}, target[3] = {kTarget.x, kTarget.y, kTarget.z};
    ASSERT_EQ(gbl_dump_test_from_c(gBuffer_.id(), kW, kH, cdir.c_str(), eye, target, kFov, kNear, kFar, message,
                                   sizeof message),
              GBL_DUMP_OK)
        << message;
    for (char const* file : {"gPosition.pfm", "gNormal.pfm", "gAlbedoSpec.ppm", "gAlbedoSpec_a.pgm", "depth.pfm"}) {
        std::string const a = fileBytes(dir + "/" + file), b = fileBytes(cdir + "/" + file);
        EXPECT_FALSE(a.empty()) << file;
        EXPECT_TRUE(a == b) << file << " differs between the C and C++ builds";
    }
    ImportedGBuffer const gc = open(cdir);
    expectSceneValues(gc);
    ASSERT_TRUE(gc.camera);
    for (int col = 0; col < 4; ++col)
        for (int r = 0; r < 4; ++r) {
            // lookAt and perspective again, in the importer: the same float operations, so at most
            // rounding of the text form (9 digits) apart.
            EXPECT_NEAR(gc.camera->view[col][r], view[col][r], 1e-6f) << col << "," << r;
            EXPECT_NEAR(gc.camera->projection[col][r], projection[col][r], 1e-6f) << col << "," << r;
        }
    GBufferCheckReport const cReport = checkGBuffer(gc);
    for (auto const& f : cReport.findings) ADD_FAILURE() << "C build: " << f.check << ": " << f.cause;
}

// A lighting pass as LearnOpenGL's deferred chapter describes it, written for this test: full screen
// over the three targets, ambient 0.1 * albedo, per light Lambert diffuse and a Blinn-Phong highlight
// of exponent 16 (not gated by N.L), both times 1 / (1 + Kl d + Kq d^2); the sky (normal 0) stays 0.
char const* const kLightingVertex = R"(#version 330 core
void main() {
    vec2 corner = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
    gl_Position = vec4(corner, 0.0, 1.0);
})";
char const* const kLightingFragment = R"(#version 330 core
uniform sampler2D gPosition;
uniform sampler2D gNormal;
uniform sampler2D gAlbedoSpec;
uniform vec3 lightPos[2];
uniform vec3 lightColor[2];
uniform float lightLinear[2];
uniform float lightQuadratic;
uniform vec3 viewPos;
out vec4 lit;
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec3 p = texelFetch(gPosition, px, 0).rgb;
    vec3 n = texelFetch(gNormal, px, 0).rgb;
    vec4 as = texelFetch(gAlbedoSpec, px, 0);
    if (dot(n, n) == 0.0) { lit = vec4(0.0); return; }
    vec3 toEye = normalize(viewPos - p);
    vec3 sum = 0.1 * as.rgb;
    for (int i = 0; i < 2; ++i) {
        vec3 toLight = normalize(lightPos[i] - p);
        float d = length(lightPos[i] - p);
        float fall = 1.0 / (1.0 + lightLinear[i] * d + lightQuadratic * d * d);
        vec3 diffuse = max(dot(n, toLight), 0.0) * as.rgb * lightColor[i];
        vec3 highlight = lightColor[i] * pow(max(dot(n, normalize(toLight + toEye)), 0.0), 16.0) * as.a;
        sum += (diffuse + highlight) * fall;
    }
    lit = vec4(sum, 1.0);
})";

// A program of that text, end to end: its G-buffer is dumped with the header (learnopengl preset) and
// lit by its own lighting pass; `gbuffer-lab` re-lights the dump in quad mode with the manifest's
// shading and gets the program's image, within the RGBA16F target's rounding. With gbuffer-lab's
// windowed model the same comparison fails (so it can fail): the program lights past the radii.
TEST_F(GbufferDumpGlTest, ALearnOpenGlLightingPassIsReLitToTheSameImage) {
    renderGeometry();
    gl::Texture litTexture = gl::Texture::create2D(GL_RGBA32F, kW, kH, "dump test lit");
    gl::Framebuffer litTarget = gl::Framebuffer::create({&litTexture}, nullptr, "dump test lighting");
    ASSERT_FALSE(litTarget.error()) << *litTarget.error();
    std::string log;
    auto program = gl::Program::build({{GL_VERTEX_SHADER, "dump_lighting.vs", kLightingVertex},
                                       {GL_FRAGMENT_SHADER, "dump_lighting.fs", kLightingFragment}},
                                      "dump test lighting", &log);
    ASSERT_TRUE(program) << log;
    glBindFramebuffer(GL_FRAMEBUFFER, litTarget.id());
    glViewport(0, 0, kW, kH);
    program->use();
    for (int unit = 0; unit < 3; ++unit) {
        glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        glBindTexture(GL_TEXTURE_2D, std::array{position_.id(), normal_.id(), albedoSpec_.id()}[std::size_t(unit)]);
    }
    glActiveTexture(GL_TEXTURE0);
    program->set("gPosition", 0);
    program->set("gNormal", 1);
    program->set("gAlbedoSpec", 2);
    for (int i = 0; i < 2; ++i) {
        std::string const at = "[" + std::to_string(i) + "]";
        program->set("lightPos" + at, glm::make_vec3(kLightPositions.data() + 3 * i));
        program->set("lightColor" + at, glm::make_vec3(kLightColors.data() + 3 * i));
        program->set("lightLinear" + at, kLinear[std::size_t(i)]);
    }
    program->set("lightQuadratic", 1.8f);
    program->set("viewPos", kEye);
    glBindVertexArray(vao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    std::vector<float> theirs(std::size_t(kW) * kH * 4);
    glReadPixels(0, 0, kW, kH, GL_RGBA, GL_FLOAT, theirs.data());  // rows bottom-up
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    glm::mat4 const view = viewMatrix(), projection = projectionMatrix();
    LearnOpenGlDump dump(view, projection);
    gbl_dump_options& o = dump.options;
    std::string const dir = test::freshTempDir("gbl_dump_relight");
    char message[1024];
    ASSERT_EQ(gbl_dump(gBuffer_.id(), kW, kH, dir.c_str(), &o, message, sizeof message), GBL_DUMP_OK) << message;
    ImportedGBuffer const g = open(dir);
    ASSERT_EQ(g.manifest.shading, ShadingModel::LearnOpenGl);
    RelightFrame const frame = relightFrame(g);
    ASSERT_TRUE(frame.frame) << frame.error;
    // The lights lie well inside the floor's reach: most of it is past their radii.
    for (PointLight const& l : g.manifest.lights) ASSERT_LT(lightRadius(l).radius, 6.0f);

    auto relit = [&](ShadingModel shading) {
        auto r = makeRenderer(kW, kH);
        EXPECT_FALSE(r->setImportedGBuffer(*frame.frame));
        PipelineSettings s;
        s.mode = LightingMode::Quad;
        s.lightCubes = false;
        applyManifestShading(g.manifest.shininess, shading, s);
        s.ambient = glm::vec3(kLearnOpenGlAmbient);  // the program's ambient in both, so only the equation differs
        FrameStats const st = r->render({cameraOfFrame(*frame.frame), g.manifest.lights, s, true});
        EXPECT_EQ(st.glErrors, 0u);
        return r->readAttachment(Attachment::Lighting);
    };
    auto over = [&](FloatImage const& ours, double* maxErr) {
        int n = 0, covered = 0;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                // readAttachment's rows run top-down, glReadPixels' bottom-up.
                float const* t = &theirs[(std::size_t(kH - 1 - y) * kW + std::size_t(x)) * 4];
                if (t[3] == 0.0f) continue;  // the sky
                ++covered;
                bool bad = false;
                for (int c = 0; c < 3; ++c) {
                    double const e = std::abs(double(ours.at(x, y, c)) - t[c]);
                    *maxErr = std::max(*maxErr, e);
                    bad |= e > 2.0 / 2048.0 * std::abs(t[c]) + 1e-4;  // RGBA16F rounding, pow() across GLSL builds
                }
                n += bad;
            }
        EXPECT_GT(covered, kW * kH / 2);
        return n;
    };
    double maxSame = 0.0, maxWindowed = 0.0;
    EXPECT_EQ(over(relit(ShadingModel::LearnOpenGl), &maxSame), 0) << "max |ours - theirs| " << maxSame;
    EXPECT_GT(over(relit(ShadingModel::GbufferLab), &maxWindowed), kW * kH / 4)
        << "gbuffer-lab's windowed model should not match that program (max " << maxWindowed << ")";
    std::printf(
        "learnopengl re-light against the program's own lighting: max |difference| %.3g (windowed model: %.3g)\n",
        maxSame, maxWindowed);
}

// No attachment holds positions (as in G-buffers of depth, normal and colour): with depth and the camera
// the manifest rebuilds them from depth, and they match the scene.
TEST_F(GbufferDumpGlTest, PositionIsRebuiltFromDepthWhenNoAttachmentHoldsIt) {
    renderGeometry();
    glm::mat4 const view = viewMatrix(), projection = projectionMatrix();
    gbl_dump_options o;
    gbl_dump_options_learnopengl(&o);
    o.position = -1;
    gbl_dump_camera camera{};
    camera.view = glm::value_ptr(view);
    camera.projection = glm::value_ptr(projection);
    o.camera = &camera;
    std::string const dir = test::freshTempDir("gbl_dump_from_depth");
    char message[512];
    ASSERT_EQ(gbl_dump(gBuffer_.id(), kW, kH, dir.c_str(), &o, message, sizeof message), GBL_DUMP_OK) << message;
    ImportedGBuffer const g = open(dir);
    EXPECT_TRUE(g.manifest.positionFromDepth);
    EXPECT_FALSE(g.image("position"));
    expectSceneValues(g);
    for (auto const& f : checkGBuffer(g).findings) ADD_FAILURE() << f.check << ": " << f.cause;
}

// The optional emissive and occlusion roles: named in the manifest when given, and read back as the
// GL held them (here the albedo attachment's rgb as emission and its alpha as occlusion: the roles
// may share an attachment as albedo and specular do); left out of it without them.
TEST_F(GbufferDumpGlTest, EmissiveAndOcclusionRolesAreNamedWhenGiven) {
    renderGeometry();
    glm::mat4 const view = viewMatrix(), projection = projectionMatrix();
    LearnOpenGlDump dump(view, projection);
    gbl_dump_options& o = dump.options;
    char message[512];
    std::string const plain = test::freshTempDir("gbl_dump_no_emissive");
    ASSERT_EQ(gbl_dump(gBuffer_.id(), kW, kH, plain.c_str(), &o, message, sizeof message), GBL_DUMP_OK) << message;
    EXPECT_EQ(fileBytes(plain + "/manifest.json").find("emissive"), std::string::npos);
    EXPECT_EQ(fileBytes(plain + "/manifest.json").find("occlusion"), std::string::npos);

    o.emissive = 2;
    o.occlusion = 2;
    o.occlusion_channel = 3;
    std::string const dir = test::freshTempDir("gbl_dump_emissive");
    ASSERT_EQ(gbl_dump(gBuffer_.id(), kW, kH, dir.c_str(), &o, message, sizeof message), GBL_DUMP_OK) << message;
    std::string const manifest = fileBytes(dir + "/manifest.json");
    EXPECT_NE(manifest.find(R"("emissive": {"file": "gAlbedoSpec.ppm", "channels": "rgb", "encoding": "linear"})"),
              std::string::npos)
        << manifest;
    EXPECT_NE(manifest.find(R"("occlusion": {"file": "gAlbedoSpec_a.pgm", "channel": "r"})"), std::string::npos)
        << manifest;
    ImportedGBuffer const g = open(dir);
    ASSERT_EQ(g.emissive.size(), g.pixelCount());
    EXPECT_EQ(g.emissive, g.albedo);
    EXPECT_EQ(g.occlusion, g.specular);
    EXPECT_TRUE(std::any_of(g.occlusion.begin(), g.occlusion.end(), [](float v) { return v > 0.0f && v < 1.0f; }));
    for (auto const& f : checkGBuffer(g).findings) ADD_FAILURE() << f.check << ": " << f.cause;

    auto expectRefused = [&](char const* words) {
        EXPECT_EQ(gbl_dump(gBuffer_.id(), kW, kH, dir.c_str(), &o, message, sizeof message), GBL_DUMP_BAD_ARGUMENT);
        EXPECT_NE(std::string(message).find(words), std::string::npos) << message;
    };
    o.occlusion_channel = 4;
    expectRefused("options.occlusion_channel must be 0 to 3 (got 4)");
    o.occlusion_channel = 3;
    o.occlusion = 1;  // RGB16F: no fourth channel
    expectRefused("options.occlusion is colour attachment 1, which has 3 channel(s); it needs 4");
    o.occlusion = 2;
    o.emissive = 3;
    expectRefused("options.emissive must be -1 or a colour attachment below color_count 3 (got 3)");
}

// Storage other than LearnOpenGL's: 16-bit unsigned position (written as float), sRGB albedo (the
// manifest says so), two-channel normals (padded to three in the file).
TEST_F(GbufferDumpGlTest, OtherStoragesAreWrittenInTheirOwnType) {
    gl::Texture const pos16 = gl::Texture::create2D(GL_RGBA16, 8, 4, "dump test rgba16");
    gl::Texture const srgb = gl::Texture::create2D(GL_SRGB8_ALPHA8, 8, 4, "dump test srgb");
    gl::Texture const octa = gl::Texture::create2D(GL_RG16F, 8, 4, "dump test rg16f");
    gl::Framebuffer const fb = gl::Framebuffer::create({&pos16, &srgb, &octa}, nullptr, "dump test storages");
    ASSERT_FALSE(fb.error()) << *fb.error();
    glBindFramebuffer(GL_FRAMEBUFFER, fb.id());
    float const p[4] = {0.25f, 0.5f, 0.75f, 1.0f}, a[4] = {0.2f, 0.4f, 0.6f, 0.8f}, n[4] = {0.6f, -0.8f, 0, 0};
    glClearBufferfv(GL_COLOR, 0, p);
    glClearBufferfv(GL_COLOR, 1, a);
    glClearBufferfv(GL_COLOR, 2, n);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    gbl_dump_options o;
    gbl_dump_options_defaults(&o);
    o.color_count = 3;
    o.position = 0;
    o.albedo = 1;
    o.specular = 0;
    o.specular_channel = 3;
    o.normal = 2;
    o.normal_encoding = "octahedral";
    std::string const dir = test::freshTempDir("gbl_dump_storages");
    char message[512];
    ASSERT_EQ(gbl_dump(fb.id(), 8, 4, dir.c_str(), &o, message, sizeof message), GBL_DUMP_OK) << message;
    for (char const* file : {"color0.pfm", "color0_a.pfm", "color1.ppm", "color1_a.pgm", "color2.pfm"})
        EXPECT_TRUE(std::filesystem::exists(dir + "/" + file)) << file;

    ImportedGBuffer const g = open(dir);
    ASSERT_EQ(g.width, 8);
    EXPECT_EQ(g.image("position")->storage, SampleStorage::Float);
    EXPECT_EQ(g.image("specular")->storage, SampleStorage::Float);
    EXPECT_EQ(g.image("albedo")->storage, SampleStorage::Uint8);
    EXPECT_EQ(g.image("normal")->storage, SampleStorage::Float);
    ASSERT_TRUE(g.manifest.albedo);
    EXPECT_EQ(g.manifest.albedo->encoding, ColorEncoding::Srgb);  // the attachment's own encoding
    std::size_t const px = 8 * 4 - 1;
    // The 16-bit levels the GL holds come back exactly, as floats of level / 65535 (the import's last
    // pixel is the GL's (7, 0)).
    std::array<std::uint16_t, 4> held{};
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb.id());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glReadPixels(7, 0, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT, held.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(std::lround(g.image("position")->at(px, c) * 65535.0f), held[std::size_t(c)]) << c;
        // Against the cleared value: the driver's float-to-16-bit conversion may round by a level
        // (llvmpipe stores 0.75 as 49150, not 49151).
        EXPECT_NEAR(g.image("position")->at(px, c), p[c], 2.0f / 65535.0f) << c;
    }
    EXPECT_EQ(std::lround(g.image("specular")->at(px, 0) * 65535.0f), held[3]);
    // The clear stores 0.4 as byte 102 (GL_FRAMEBUFFER_SRGB is off, so it is not encoded); the manifest
    // says the storage is sRGB, so the importer decodes that byte: ((0.4 + 0.055) / 1.055)^2.4.
    EXPECT_NEAR(g.image("albedo")->at(px, 1), 102.0f / 255.0f, 1e-6f);
    EXPECT_NEAR(g.albedo[px].g, std::pow((102.0f / 255.0f + 0.055f) / 1.055f, 2.4f), 1e-5f);
    // The two channels of RG16F, padded with a third in the file and selected back by "rg"; half floats
    // hold 0.6 and -0.8 to 2^-11.
    EXPECT_EQ(g.image("normal")->channels, 2);
    EXPECT_NEAR(g.image("normal")->at(px, 0), 0.6f, 1.0f / 2048.0f);
    EXPECT_NEAR(g.image("normal")->at(px, 1), -0.8f, 1.0f / 2048.0f);
}

// Bad input: one sentence, a nonzero code, nothing aborted.
TEST_F(GbufferDumpGlTest, BadInputIsRefusedWithOneSentence) {
    char message[512];
    auto expectRefused = [&](gbl_dump_options const& o, char const* dir, int code, char const* words) {
        int const rc = gbl_dump(gBuffer_.id(), kW, kH, dir, &o, message, sizeof message);
        EXPECT_EQ(rc, code) << message;
        EXPECT_NE(std::string(message).find(words), std::string::npos) << message;
    };
    std::string const dir = test::freshTempDir("gbl_dump_bad");
    gbl_dump_options o;
    gbl_dump_options_learnopengl(&o);
    o.normal = -1;
    expectRefused(o, dir.c_str(), GBL_DUMP_BAD_ARGUMENT, "options.normal must name");
    gbl_dump_options_learnopengl(&o);
    o.specular = 0;  // RGB16F: no fourth channel
    expectRefused(o, dir.c_str(), GBL_DUMP_BAD_ARGUMENT, "has 3 channel(s); it needs 4");
    gbl_dump_options_learnopengl(&o);
    o.color_count = 4;
    expectRefused(o, dir.c_str(), GBL_DUMP_BAD_FRAMEBUFFER, "colour attachment 3 has nothing attached");
    gbl_dump_options_learnopengl(&o);
    o.names[1] = "gPosition";
    expectRefused(o, dir.c_str(), GBL_DUMP_BAD_ARGUMENT, "one file would overwrite the other");
    gbl_dump_options_learnopengl(&o);
    o.position = -1;  // no position, and no camera to rebuild it from depth
    expectRefused(o, dir.c_str(), GBL_DUMP_BAD_ARGUMENT, "options.position must name");
    gbl_dump_options_learnopengl(&o);
    std::string const missing = dir + "/no/such/folder";
    expectRefused(o, missing.c_str(), GBL_DUMP_WRITE_FAILED, ("cannot write " + missing + "/gPosition.pfm").c_str());
    EXPECT_FALSE(std::filesystem::exists(dir + "/manifest.json"));

    // A framebuffer without depth when depth is asked for; one with integer storage.
    gl::Texture const color = gl::Texture::create2D(GL_RGBA8, 4, 4, "dump test colour");
    gl::Texture const integer = gl::Texture::create2D(GL_R32UI, 4, 4, "dump test integer");
    gl::Framebuffer const noDepth = gl::Framebuffer::create({&color, &integer}, nullptr, "dump test no depth");
    ASSERT_FALSE(noDepth.error()) << *noDepth.error();
    gbl_dump_options_defaults(&o);
    o.position = o.normal = 0;
    o.depth = 1;
    EXPECT_EQ(gbl_dump(noDepth.id(), 4, 4, dir.c_str(), &o, message, sizeof message), GBL_DUMP_BAD_FRAMEBUFFER);
    EXPECT_NE(std::string(message).find("has no depth attachment"), std::string::npos) << message;
    o.depth = 0;
    o.color_count = 2;
    EXPECT_EQ(gbl_dump(noDepth.id(), 4, 4, dir.c_str(), &o, message, sizeof message), GBL_DUMP_BAD_FRAMEBUFFER);
    EXPECT_NE(std::string(message).find("colour attachment 1 has integer storage"), std::string::npos) << message;
    EXPECT_EQ(gbl_dump(0, 4, 4, dir.c_str(), &o, message, sizeof message), GBL_DUMP_BAD_ARGUMENT);
    EXPECT_NE(std::string(message).find("framebuffer 0 is the window's"), std::string::npos) << message;

    gbl_dump_options_learnopengl(&o);
    gbl_dump_lights lights{};
    float const lightPosition[3] = {0, 1, 0}, lightColor[3] = {1, 1, 1};
    lights.count = 1;
    lights.positions = lightPosition;
    lights.colors = lightColor;
    lights.linear = 0.7f;
    lights.quadratic = -1.8f;
    o.lights = &lights;
    expectRefused(o, dir.c_str(), GBL_DUMP_BAD_ARGUMENT, "light 0 needs");

    // An error the caller's code raised before the call is reported as such, not as the read's.
    gbl_dump_options_learnopengl(&o);
    glBindFramebuffer(GL_FRAMEBUFFER, 4000000);  // never generated: GL_INVALID_OPERATION in a core profile
    expectRefused(o, dir.c_str(), GBL_DUMP_GL_ERROR, "GL_INVALID_OPERATION was raised before gbl_dump was called");
    acceptGlErrors();
    EXPECT_FALSE(std::filesystem::exists(dir + "/manifest.json"));
}
