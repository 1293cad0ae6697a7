// The GL state each pass draws under is the state its declaration gives (core/frame_passes.h): every declared
// pass of every mode x layout x cull x accumulation (prepass: its light pass) x depth copy, on small frames, with
// the state read back after each draw and dispatch and compared with the pass's declared draw groups. Shown to
// fail when a declaration the executor runs is changed by hand, and that a test's own pass runs from one of each.
#include "gpu/draw_state_gl.h"
#include "core/gbuffer_layout.h"
#include "gl/draw_count.h"
#include "gl/framebuffer.h"
#include "gl/fullscreen_triangle.h"
#include "gl/program.h"
#include "gl_fixture.h"
#include "gpu/gpu_scene.h"
#include "renderer_test_access.h"
#include "scene/default_scene.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>

using namespace gbl;

namespace {

constexpr int kW = 64, kH = 48;  // small: the state is what is checked, not the image

// The fixed-function state a draw ran under, read back from GL.
struct GlState {
    bool depthTest = false;
    GLint depthFunc = 0;
    GLboolean depthMask = GL_FALSE;
    bool blend = false;
    GLint blendSrc = 0, blendDst = 0, blendEquation = 0;
    bool cull = false;
    GLint cullFace = 0;
    bool stencil = false;
    GLint stencilFunc = 0, stencilRef = 0, stencilValueMask = 0;
    GLint frontZFail = 0, backZFail = 0, frontPass = 0, frontFail = 0;
    GLint stencilWriteMask = 0;
    bool sampleMask = false;
    GLboolean colorMask[4]{};
    bool operator==(GlState const&) const = default;
};

GlState readGlState() {
    GlState s;
    s.depthTest = glIsEnabled(GL_DEPTH_TEST);
    glGetIntegerv(GL_DEPTH_FUNC, &s.depthFunc);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &s.depthMask);
    s.blend = glIsEnabled(GL_BLEND);
    glGetIntegerv(GL_BLEND_SRC_RGB, &s.blendSrc);
    glGetIntegerv(GL_BLEND_DST_RGB, &s.blendDst);
    glGetIntegerv(GL_BLEND_EQUATION_RGB, &s.blendEquation);
    s.cull = glIsEnabled(GL_CULL_FACE);
    glGetIntegerv(GL_CULL_FACE_MODE, &s.cullFace);
    s.stencil = glIsEnabled(GL_STENCIL_TEST);
    glGetIntegerv(GL_STENCIL_FUNC, &s.stencilFunc);
    glGetIntegerv(GL_STENCIL_REF, &s.stencilRef);
    glGetIntegerv(GL_STENCIL_VALUE_MASK, &s.stencilValueMask);
    glGetIntegerv(GL_STENCIL_FAIL, &s.frontFail);
    glGetIntegerv(GL_STENCIL_PASS_DEPTH_FAIL, &s.frontZFail);
    glGetIntegerv(GL_STENCIL_PASS_DEPTH_PASS, &s.frontPass);
    glGetIntegerv(GL_STENCIL_BACK_PASS_DEPTH_FAIL, &s.backZFail);
    glGetIntegerv(GL_STENCIL_WRITEMASK, &s.stencilWriteMask);
    s.sampleMask = glIsEnabled(GL_SAMPLE_MASK);
    glGetBooleanv(GL_COLOR_WRITEMASK, s.colorMask);
    return s;
}

// Whether `gl` is what `d` declares, written from the declaration's meaning (core/frame_passes.h),
// not from apply(): the enabled tests and their functions, the write masks, the blend factors and
// the stencil operations. A state that is off is only checked for being off.
std::string mismatch(GlState const& gl, DrawState const& d) {
    std::ostringstream why;
    auto check = [&](bool ok, char const* what) {
        if (!ok) why << what << "; ";
    };
    check(gl.depthTest == (d.depthTest != DepthTest::Off), "depth test enable");
    if (d.depthTest != DepthTest::Off) {
        GLint const f = d.depthTest == DepthTest::Less           ? GL_LESS
                        : d.depthTest == DepthTest::LessEqual    ? GL_LEQUAL
                        : d.depthTest == DepthTest::GreaterEqual ? GL_GEQUAL
                                                                 : GL_ALWAYS;
        check(gl.depthFunc == f, "depth func");
        check(bool(gl.depthMask) == d.depthWrite, "depth write");
    }
    check(gl.blend == (d.blend != Blend::Off), "blend enable");
    if (d.blend == Blend::Add)
        check(gl.blendSrc == GL_ONE && gl.blendDst == GL_ONE && gl.blendEquation == GL_FUNC_ADD, "blend add");
    if (d.blend == Blend::Alpha)
        check(gl.blendSrc == GL_SRC_ALPHA && gl.blendDst == GL_ONE_MINUS_SRC_ALPHA && gl.blendEquation == GL_FUNC_ADD,
              "blend alpha");
    check(gl.cull == (d.cull != FaceCull::Off), "cull enable");
    if (d.cull == FaceCull::Back) check(gl.cullFace == GL_BACK, "cull back");
    if (d.cull == FaceCull::Front) check(gl.cullFace == GL_FRONT, "cull front");
    // msaa edges: the complex bit (core/frame_passes.h, kComplexStencilBit) tested beside the use,
    // whose marks then keep to the bits below it.
    GLint const bit = kComplexStencilBit;
    bool const pixels = d.pixels != MsaaPixels::All;
    GLint const pixelRef = d.pixels == MsaaPixels::Complex ? bit : 0;
    GLint const marks = pixels ? 0xFF & ~bit : 0xFF;
    check(gl.stencil == (d.stencil != StencilUse::Off || pixels), "stencil enable");
    if (d.stencil == StencilUse::Mark)
        check(gl.stencilFunc == (pixels ? GL_EQUAL : GL_ALWAYS) && gl.backZFail == GL_INCR_WRAP &&
                  gl.frontZFail == GL_DECR_WRAP && gl.stencilWriteMask == marks,
              "stencil mark");
    if (d.stencil == StencilUse::ShadeMarked)
        check(gl.stencilFunc == GL_EQUAL && gl.stencilRef == (1 | pixelRef) && gl.stencilValueMask == 0xFF &&
                  gl.frontFail == GL_ZERO && gl.frontZFail == GL_ZERO && gl.frontPass == GL_ZERO &&
                  gl.stencilWriteMask == marks,
              "stencil shade marked");
    if (d.stencil == StencilUse::EqualBits)
        check(gl.stencilFunc == GL_EQUAL && gl.stencilRef == d.stencilRef && gl.stencilValueMask == d.stencilRef &&
                  gl.frontFail == GL_KEEP && gl.frontZFail == GL_KEEP && gl.frontPass == GL_KEEP,
              "stencil equal bits");
    if (d.stencil == StencilUse::MarkComplex)
        check(gl.stencilFunc == GL_ALWAYS && gl.stencilRef == bit && gl.frontPass == GL_REPLACE &&
                  gl.stencilWriteMask == bit,
              "stencil mark complex");
    if (d.stencil == StencilUse::Off && pixels)
        check(gl.stencilFunc == GL_EQUAL && gl.stencilRef == pixelRef && gl.stencilValueMask == bit &&
                  gl.frontPass == GL_KEEP && gl.frontZFail == GL_KEEP && gl.stencilWriteMask == 0,
              "stencil simple or complex pixels");
    check(!gl.sampleMask, "sample mask off (msaa lights into single-sample targets)");
    bool const colour = gl.colorMask[0] && gl.colorMask[1] && gl.colorMask[2] && gl.colorMask[3];
    bool const none = !gl.colorMask[0] && !gl.colorMask[1] && !gl.colorMask[2] && !gl.colorMask[3];
    check(d.colorWrite ? colour : none, "colour write");
    return why.str();
}

class DrawStateGlTest : public test::CourtyardGlTest {
protected:
    DrawStateGlTest() : CourtyardGlTest(kW, kH) {}

    void TearDown() override {
        gl::drawObserver() = {};
        if (renderer_) {
            RendererTestAccess::setPassObserver(*renderer_, {});
            RendererTestAccess::editDeclarations(*renderer_, {});
        }
        CourtyardGlTest::TearDown();
    }

    // Renders `input` with each draw's state compared with the declared states of the pass it
    // belongs to, as Renderer::framePasses lists them (not as the executor was handed them).
    // Returns one line per draw whose state matched none of them.
    // `extra`: the test's own passes (RendererTestAccess::addPass), which framePasses() never lists.
    std::vector<std::string> checkFrame(FrameInput const& input, std::string const& label,
                                        std::vector<PassDecl> const& extra = {}) {
        std::map<std::string, PassDecl> declared;
        for (PassDecl const& p : renderer_->framePasses(input)) declared[std::string(p.name())] = p;
        for (PassDecl const& p : extra) declared[std::string(p.name())] = p;
        std::string running;
        std::vector<std::string> failures;
        RendererTestAccess::setPassObserver(*renderer_, [&](PassDecl const& p) { running = p.name(); });
        gl::drawObserver() = [&] {
            auto const it = declared.find(running);
            if (it == declared.end()) {
                failures.push_back(label + ": a draw in '" + running + "', which framePasses() does not list");
                return;
            }
            PassDecl const& p = it->second;
            if (p.kind == PassKind::Compute) {
                ++dispatches_;
                return;  // no fixed-function state in a dispatch
            }
            GlState const now = readGlState();
            std::string whyNot = "declares no draw state";
            std::ptrdiff_t fewest = -1;  // the declared group closest to the state found, named in the failure
            for (DrawState const& d : p.states) {
                std::string const why = mismatch(now, d);
                if (why.empty()) {
                    ++checked_[running];
                    ++checkedGroups_[running + ": " + std::string(d.what)];
                    return;
                }
                std::ptrdiff_t const differences = std::count(why.begin(), why.end(), ';');
                if (fewest >= 0 && differences >= fewest) continue;
                fewest = differences;
                whyNot = std::string(d.what) + ": " + why;
            }
            failures.push_back(label + ": pass " + running + " drew under a state it does not declare (" + whyNot +
                               ")");
        };
        FrameStats const stats = renderer_->render(input);
        gl::drawObserver() = {};
        RendererTestAccess::setPassObserver(*renderer_, {});
        EXPECT_EQ(stats.glErrors, 0u) << label;
        return failures;
    }

    std::map<std::string, int> checked_;        // draws checked per pass
    std::map<std::string, int> checkedGroups_;  // per "pass: group", the group whose state a draw matched first
    int dispatches_ = 0;
};

TEST_F(DrawStateGlTest, EveryPassOfEveryCombinationDrawsUnderItsDeclaredState) {
    std::vector<std::string> failures;
    int frames = 0, rendered = 0;
    // Combinations that declare the very same passes (the cull mode outside the volumes mode, say)
    // draw the very same frame: each distinct declaration is rendered once.
    std::vector<std::vector<PassDecl>> seen;
    for (std::size_t layout = 0; layout < kGBufferLayoutNames.size(); ++layout)  // outermost: a rebuild each
        for (std::size_t mode = 0; mode < kLightingModeNames.size(); ++mode)
            for (std::size_t cull = 0; cull < kCullModeNames.size(); ++cull)
                for (std::size_t acc = 0; acc < kLightAccumulationNames.size(); ++acc)
                    for (std::size_t copy = 0; copy < kDepthCopyNames.size(); ++copy)
                        for (DebugView view : {DebugView::Final, DebugView::Heatmap, DebugView::TileLights}) {
                            PipelineSettings s;
                            s.layout = GBufferLayout(layout);
                            s.mode = LightingMode(mode);
                            s.cull = CullMode(cull);
                            s.accumulation = LightAccumulation(acc);
                            s.prepassLights = PrepassLights(acc && view == DebugView::Final);  // prepass ignores split
                            s.depthCopy = DepthCopy(copy);
                            s.view = view;
                            s.lightCubes = s.volumeWireframes = true;  // drawn on the final view only
                            std::string const label =
                                std::string(kGBufferLayoutNames[layout]) + " " + std::string(kLightingModeNames[mode]) +
                                " " + std::string(kCullModeNames[cull]) + " " +
                                std::string(kLightAccumulationNames[acc]) + " " + std::string(kDepthCopyNames[copy]) +
                                " view " + std::to_string(int(view));
                            ++frames;
                            FrameInput const input{camera_, lights_, s};
                            std::vector<PassDecl> passes = renderer_->framePasses(input);
                            if (std::find(seen.begin(), seen.end(), passes) != seen.end()) continue;
                            seen.push_back(std::move(passes));
                            ++rendered;
                            for (std::string const& f : checkFrame(input, label)) failures.push_back(f);
                            // The camera inside a light's volume: flip's second group (back faces).
                            if (!drawsLightVolumes(s) || view != DebugView::Final) continue;
                            Camera inside = camera_;
                            inside.position = lights_.front().position;
                            for (std::string const& f : checkFrame({inside, lights_, s}, label + " inside"))
                                failures.push_back(f);
                        }
    EXPECT_EQ(frames, 4 * int(kLightingModeNames.size()) * 5 * 2 * 3 * 3);
    EXPECT_GT(rendered, 4 * (5 + 4) * 2 * 3) << "at least every cull mode of the volumes mode";
    std::string all;
    for (std::size_t i = 0; i < failures.size() && i < 20; ++i) all += failures[i] + "\n";
    EXPECT_TRUE(failures.empty()) << failures.size() << " draws under an undeclared state, first ones:\n" << all;
    // Every raster pass that draws was checked, the volumes' every group among them.
    // (The default scene has no blended surface: the forward pass draws nothing there.)
    for (char const* pass : {"forward_shading", "geometry", "lighting", "light_combine", "depth_copy", "light_cubes",
                             "wireframes", "coverage", "display", "depth_prepass"})
        EXPECT_GT(checked_[pass], 0) << pass << " drew nothing that was checked";
}

// The default scene's glass panes (DefaultSceneOptions::glass): the forward pass draws them, sorted,
// under its declared state (alpha blend, depth tested and not written) in every mode and with every
// depth copy, the draws of the other passes still under theirs.
TEST_F(DrawStateGlTest, TheGlassPassDrawsUnderItsDeclaredState) {
    ASSERT_FALSE(renderer_->setScene(makeDefaultScene({int(lights_.size()), true})));
    std::vector<std::string> failures;
    for (std::size_t mode = 0; mode < kLightingModeNames.size(); ++mode)
        for (std::size_t copy = 0; copy < kDepthCopyNames.size(); ++copy) {
            PipelineSettings s;
            s.mode = LightingMode(mode);
            s.depthCopy = DepthCopy(copy);
            s.lightCubes = true;
            s.glassOutline = true;
            std::string const label =
                "glass " + std::string(kLightingModeNames[mode]) + " " + std::string(kDepthCopyNames[copy]);
            for (std::string const& f : checkFrame({camera_, lights_, s}, label)) failures.push_back(f);
        }
    std::string all;
    for (std::size_t i = 0; i < failures.size() && i < 20; ++i) all += failures[i] + "\n";
    EXPECT_TRUE(failures.empty()) << failures.size() << " draws under an undeclared state, first ones:\n" << all;
    // Three panes a frame, every frame: each pane's draw was checked against the blended declaration.
    int const frames = int(kLightingModeNames.size() * kDepthCopyNames.size());
    EXPECT_EQ(checked_["forward"], frames * int(std::size(kGlassPanes)));
    EXPECT_EQ(checked_["glass_outline"], frames * int(std::size(kGlassPanes)));
}

// msaa (docs/msaa.md): every lighting strategy at 2 and 4 samples, with each depth copy and the
// counted view, in the quad mode and classic layout that light a multisampled G-buffer; its
// detection, simple and complex passes draw under their declared stencil states.
TEST_F(DrawStateGlTest, EveryMsaaCombinationDrawsUnderItsDeclaredState) {
    ASSERT_GE(caps().maxMsaaSamples(), 4) << "this context offers fewer than 4 samples per pixel";
    std::vector<std::string> failures;
    int rendered = 0;
    for (Msaa msaa : {Msaa::X2, Msaa::X4})
        for (std::size_t lit = 0; lit < kMsaaLightingNames.size(); ++lit)
            for (std::size_t copy = 0; copy < kDepthCopyNames.size(); ++copy)
                for (DebugView view : {DebugView::Final, DebugView::Heatmap}) {
                    PipelineSettings s;
                    s.msaa = msaa;
                    s.msaaLighting = MsaaLighting(lit);
                    s.depthCopy = DepthCopy(copy);
                    s.view = view;
                    s.lightCubes = s.volumeWireframes = true;
                    std::string const label = "msaa " + std::string(kMsaaNames[std::size_t(msaa)]) + " " +
                                              std::string(kMsaaLightingNames[lit]) + " " +
                                              std::string(kDepthCopyNames[copy]) + " view " + std::to_string(int(view));
                    ++rendered;
                    for (std::string const& f : checkFrame({camera_, lights_, s}, label)) failures.push_back(f);
                }
    EXPECT_EQ(rendered, 2 * 3 * 3 * 2);
    std::string all;
    for (std::size_t i = 0; i < failures.size() && i < 20; ++i) all += failures[i] + "\n";
    EXPECT_TRUE(failures.empty()) << failures.size() << " draws under an undeclared state, first ones:\n" << all;
    for (char const* pass : {"geometry", "msaa_edges", "lighting", "lighting_complex", "depth_copy", "display"})
        EXPECT_GT(checked_[pass], 0) << pass << " drew nothing that was checked";
}

// msaa in volumes mode (the simple and complex pixels' groups, the complex bit beside the volumes'
// stencil marks) with every cull mode, and in a layout that rebuilds position.
TEST_F(DrawStateGlTest, EveryMsaaVolumesCullModeAndLayoutDrawsUnderItsDeclaredState) {
    // per-sample with every cull mode, edges with the two that use the stencil differently (stencil
    // shares it with the complex bit; flip has two groups per draw): 2 samples keep it short. Then a
    // layout that rebuilds position. The volumes test the lit target's depth-stencil: the resolved
    // depth beside the complex bit.
    std::vector<PipelineSettings> frames;
    for (std::size_t cull = 0; cull < kCullModeNames.size() + 2; ++cull) {
        PipelineSettings s;
        s.mode = LightingMode::Volumes;
        s.cull = cull < kCullModeNames.size()    ? CullMode(cull)
                 : cull == kCullModeNames.size() ? CullMode::Flip
                                                 : CullMode::Stencil;
        s.msaa = Msaa::X2;
        s.msaaLighting = cull < kCullModeNames.size() ? MsaaLighting::PerSample : MsaaLighting::Edges;
        frames.push_back(s);
    }
    for (LightingMode mode : {LightingMode::Quad, LightingMode::Volumes}) {
        PipelineSettings s;
        s.layout = GBufferLayout::Packed;
        s.mode = mode;
        s.cull = CullMode::Stencil;
        s.msaa = Msaa::X2;
        s.msaaLighting = MsaaLighting::Edges;
        frames.push_back(s);
    }
    std::vector<std::string> failures;
    for (PipelineSettings const& s : frames) {
        std::string const label = "msaa 2 " + std::string(enumName(kGBufferLayoutNames, s.layout)) + " " +
                                  std::string(enumName(kLightingModeNames, s.mode)) + " " +
                                  std::string(enumName(kMsaaLightingNames, s.msaaLighting)) + " cull " +
                                  std::string(enumName(kCullModeNames, s.cull));
        std::vector<PassDecl> const passes = renderer_->framePasses({camera_, lights_, s});
        bool const resolvedDepth = std::any_of(passes.begin(), passes.end(), [](PassDecl const& p) {
            return p.id == PassId::VolumeDepth && p.samples == std::vector{Resource::MsaaDepth} &&
                   p.depthStencil == Resource::LitDepth && p.depthWrite && !p.stencilWrite;
        });
        EXPECT_EQ(resolvedDepth, s.mode == LightingMode::Volumes) << label << ": the depth alone, the complex bit kept";
        for (std::string const& f : checkFrame({camera_, lights_, s}, label)) failures.push_back(f);
    }
    std::string all;
    for (std::size_t i = 0; i < failures.size() && i < 20; ++i) all += failures[i] + "\n";
    EXPECT_TRUE(failures.empty()) << failures.size() << " draws under an undeclared state, first ones:\n" << all;
    for (char const* pass : {"msaa_edges", "lighting", "lighting_complex"})
        EXPECT_GT(checked_[pass], 0) << pass << " drew nothing that was checked";
    EXPECT_GT(checkedGroups_["lighting: volumes: front faces"], 0) << "the volumes' draws";
}

// The check is not vacuous: the light cubes' declaration changed by hand in the passes the
// executor runs (depth test LESS to ALWAYS) is caught, as draws under a state framePasses() does
// not list.
TEST_F(DrawStateGlTest, AChangedDeclarationIsCaught) {
    PipelineSettings s;
    s.lightCubes = true;
    RendererTestAccess::editDeclarations(*renderer_, [](std::vector<PassDecl>& passes) {
        for (PassDecl& p : passes)
            if (p.id == PassId::LightCubes) p.states.front().depthTest = DepthTest::Always;
    });
    std::vector<std::string> const failures = checkFrame({camera_, lights_, s}, "edited");
    ASSERT_FALSE(failures.empty());
    std::printf("caught %zu draws, the first: %s\n", failures.size(), failures.front().c_str());
    EXPECT_NE(failures.front().find("pass light_cubes drew under a state it does not declare (cubes: depth func"),
              std::string::npos)
        << failures.front();
    RendererTestAccess::editDeclarations(*renderer_, {});
    EXPECT_TRUE(checkFrame({camera_, lights_, s}, "restored").empty());
}

// glTF's double-sided materials are drawn with no culling and every other material with back faces
// culled, each under its declared group (drawScene applies them): the courtyard with every other
// material made double-sided and one made blended, in forward mode and in a deferred one. Each
// double-sided draw is counted under the double-sided group, so the two groups were both applied.
TEST_F(DrawStateGlTest, DoubleSidedMaterialsDrawUnderTheirDeclaredGroup) {
    SceneData scene = scene_;
    ASSERT_GE(scene.materials.size(), 2u);
    for (std::size_t i = 0; i < scene.materials.size(); i += 2) scene.materials[i].doubleSided = true;
    scene.materials[1].alphaMode = AlphaMode::Blend;
    scene.materials[1].doubleSided = true;
    scene.materials[1].baseColorFactor.a = 0.5f;
    // The draws drawScene makes of each kind (every instance, whatever it covers on screen).
    int opaqueDouble = 0, opaqueSingle = 0, blendedDouble = 0;
    for (MeshInstance const& inst : scene.instances) {
        int const m = scene.meshes[std::size_t(inst.mesh)].material;
        Material const mat = m >= 0 ? scene.materials[std::size_t(m)] : Material{};
        bool const blended = mat.alphaMode == AlphaMode::Blend;
        opaqueDouble += !blended && mat.doubleSided;
        opaqueSingle += !blended && !mat.doubleSided;
        blendedDouble += blended && mat.doubleSided;
    }
    ASSERT_GT(opaqueDouble, 0);
    ASSERT_GT(opaqueSingle, 0);
    ASSERT_GT(blendedDouble, 0);
    ASSERT_FALSE(renderer_->setScene(scene));
    for (LightingMode mode : {LightingMode::Forward, LightingMode::Quad}) {
        PipelineSettings s;
        s.mode = mode;
        checkedGroups_.clear();
        std::string const label(enumName(kLightingModeNames, mode));
        std::vector<std::string> const failures = checkFrame({camera_, lights_, s}, label);
        EXPECT_TRUE(failures.empty()) << failures.size() << " draws, the first: " << failures.front();
        std::string const opaquePass = mode == LightingMode::Forward ? "forward_shading" : "geometry";
        EXPECT_EQ(checkedGroups_[opaquePass + ": double-sided opaque surfaces"], opaqueDouble) << label;
        EXPECT_EQ(checkedGroups_[opaquePass + ": opaque surfaces"], opaqueSingle) << label;
        EXPECT_EQ(checkedGroups_["forward: double-sided blended surfaces"], blendedDouble) << label;
    }
}

// The browser's read-back draws (renderer_readback.cpp, built for WebGL2 only) run under their
// declared groups through apply(): each group applied here reads back as it declares, the stencil
// groups testing one bit each (the state of bit 3 is not that of bit 2).
TEST_F(DrawStateGlTest, TheReadbackDrawsDeclaredStatesApplyAsDeclared) {
    // The read-back's target: a colour image over a depth-stencil. GL reads the stencil reference
    // back clamped to the bound framebuffer's stencil bits, so one with 8 of them is bound.
    gl::Texture const color = gl::Texture::create2D(GL_RGBA8, kW, kH, "test.readback");
    gl::Texture const depth = gl::Texture::create2D(GL_DEPTH32F_STENCIL8, kW, kH, "test.readback_depth");
    gl::Framebuffer const fbo = gl::Framebuffer::create({&color}, &depth, "test.readback");
    ASSERT_TRUE(fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    for (bool stencil : {false, true}) {
        PassDecl const decl = readbackPass(stencil);
        ASSERT_EQ(decl.states.size(), stencil ? 8u : 1u);
        for (std::size_t i = 0; i < decl.states.size(); ++i) {
            apply(kWriteAll);  // whatever came before
            applyGroup(decl.states, i);
            EXPECT_EQ(mismatch(readGlState(), decl.states[i]), "") << decl.name() << " " << decl.states[i].what;
        }
    }
    PassDecl const stencil = readbackPass(true);
    apply(stencil.states[3]);
    EXPECT_NE(mismatch(readGlState(), stencil.states[2]), "") << "bit 3's state passes for bit 2's";
    apply(kWriteAll);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

// A pass of the test's own: one declaration (what it draws into, with which state) and one run
// function, run by the same executor after the display pass. It adds a constant over the display
// image under its declared additive blend; the check above holds for it too.
TEST_F(DrawStateGlTest, APassIsOneDeclarationAndOneRunFunction) {
    std::string log;
    auto program = gl::Program::build(
        {{GL_VERTEX_SHADER, "tint.vert",
          "#version 330 core\nvoid main() { vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);\n"
          "gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0); }\n"},
         {GL_FRAGMENT_SHADER, "tint.frag",
          "#version 330 core\nout vec4 color; void main() { color = vec4(0.0, 0.0, 0.25, 0.0); }\n"}},
        "test tint", &log);
    ASSERT_TRUE(program) << log;
    gl::FullscreenTriangle const triangle = gl::FullscreenTriangle::create();

    PipelineSettings s;
    s.lightCubes = false;
    FrameInput const input{camera_, lights_, s};
    renderer_->render(input);
    FloatImage const before = renderer_->readAttachment(Attachment::Final);

    // --- the pass: its declaration ...
    PassDecl tint;
    tint.customName = "test_tint";
    tint.color = {Resource::Display};
    tint.states = {{"tint", DepthTest::Off, false, Blend::Add, FaceCull::Off}};
    // ... and its run function.
    RendererTestAccess::addPass(*renderer_, PassId::Display, tint, [&](PassRun const& r) {
        glBindFramebuffer(GL_FRAMEBUFFER, r.fbo->id());
        applyGroup(r.decl.states, 0);
        program->use();
        triangle.draw();
    });
    // ---

    std::vector<std::string> const failures = checkFrame(input, "tinted", {tint});
    EXPECT_TRUE(failures.empty()) << failures.front();
    EXPECT_GT(checked_["test_tint"], 0);
    FrameStats const stats = renderer_->render(input);
    ASSERT_FALSE(stats.calls.empty());
    EXPECT_EQ(stats.calls.back().name, "test_tint") << "it runs after the display pass, counted under its name";
    EXPECT_EQ(stats.calls.back().draws, 1u);
    FloatImage const after = renderer_->readAttachment(Attachment::Final);
    ASSERT_EQ(after.width, before.width);
    // Blue up by 0.25 (64/255 in RGBA8: 1/255 either way for the rounding of the stored sum),
    // clamped at 1; red and green untouched.
    int raised = 0;
    for (int y = 0; y < before.height; ++y)
        for (int x = 0; x < before.width; ++x) {
            EXPECT_EQ(after.at(x, y, 0), before.at(x, y, 0));
            EXPECT_EQ(after.at(x, y, 1), before.at(x, y, 1));
            float const want = std::min(before.at(x, y, 2) + 0.25f, 1.0f);
            EXPECT_NEAR(after.at(x, y, 2), want, 1.0f / 255.0f) << x << "," << y;
            raised += after.at(x, y, 2) > before.at(x, y, 2);
        }
    EXPECT_GT(raised, before.width * before.height / 2);
    RendererTestAccess::clearPasses(*renderer_);
}

}  // namespace
