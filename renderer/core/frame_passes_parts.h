// The pieces frame_passes.cpp declares passes with, shared with the msaa passes' declarations
// (frame_passes_msaa.cpp). Internal to core/: plain values, no GL.
#pragma once

#include "core/frame_passes.h"
#include "core/gbuffer_layout.h"

#include <initializer_list>
#include <string_view>
#include <vector>

namespace gbl::detail {

PassDecl declare(PassId id, PassKind kind = PassKind::Raster);
DrawState state(std::string_view what, DepthTest depthTest, bool depthWrite, Blend blend, FaceCull cull,
                StencilUse stencil = StencilUse::Off, bool colorWrite = true);
// The layout's target of a G-buffer slot.
Resource slotResource(GBufferSlot slot);
// What shaders/gbuffer_read.glsl samples in `layout`: position, or the depth it is rebuilt from.
std::vector<Resource> gbufferSamples(GBufferLayoutDesc const& d);
// `a` with those of `b` it lacks.
std::vector<Resource> plus(std::vector<Resource> a, std::initializer_list<Resource> b);
DrawState fullScreen(std::string_view what);
// `drawn` kept to the msaa simple or complex pixels (core/frame_passes.h).
DrawState onPixels(DrawState drawn, MsaaPixels pixels);
// passes/light_volumes.cpp, drawLightVolumes: the draws of one cull mode, each added (blend ONE, ONE).
std::vector<DrawState> volumeStates(CullMode cull);
// The volumes drawn into `color` against the volume depth-stencil (lighting and coverage).
PassDecl volumePass(PassId id, GBufferLayoutDesc const& d, CullMode cull, std::vector<Resource> color);
// The copy of the depth-stencil `source` the volume passes test against, where they sample it.
PassDecl volumeDepthPass(Resource source = Resource::GBufferDepth);

// --- msaa (docs/msaa.md; frame_passes_msaa.cpp) ----------------------------------------------------

// The multisampled twins of the layout's colour attachments, in draw-buffer order.
std::vector<Resource> msaaColor(GBufferLayoutDesc const& d);
// What the lighting reads of the multisampled G-buffer: gbufferSamples' twins.
std::vector<Resource> msaaGBufferSamples(GBufferLayoutDesc const& d);
// Whether the frame lights a multisampled G-buffer (the renderer turns msaa off where it cannot, and
// says why: core/msaa.h).
bool msaaFrame(PipelineSettings const& s, bool imported);
// Whether its lighting reads the samples themselves (not the resolved G-buffer).
bool lightsSamples(PipelineSettings const& s);
PassDecl msaaEdgesPass(GBufferLayoutDesc const& d);
PassDecl msaaResolvePass(GBufferLayoutDesc const& d);
PassDecl msaaVolumesPass(PipelineSettings const& s, GBufferLayoutDesc const& d);
PassDecl msaaVolumeDepthPass();
PassDecl lightingComplexPass(GBufferLayoutDesc const& d);

}  // namespace gbl::detail
