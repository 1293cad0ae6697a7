// Clustered lighting passes: list building and shading.
#include "passes/lighting_clustered.h"
#include "gl/draw_count.h"

#include "gl/shader_bindings.h"

#include <algorithm>

namespace gbl {

namespace {

void setGridUniforms(gl::Program const& p, LightingClusteredInput const& in, LightingClusteredConfig const& c,
                     ClusterGrid const& g) {
    // Both programs must agree on the list length, and it is only known once the lists exist.
    p.set("uView", c.view);
    glUniform2i(p.uniform("uScreenSize"), c.width, c.height);
    glUniform3i(p.uniform("uGrid"), g.tilesX, g.tilesY, g.slices);
    p.set("uMaxLights", in.lists.cap);
    p.set("uNear", c.nearPlane);
    p.set("uFar", c.farPlane);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_CLUSTER_COUNTS, in.lists.counts.id());
}

}  // namespace

void clusterListsPass(LightingClusteredInput const& in, LightingClusteredConfig const& c) {
    ClusterGrid const g = clusterGrid(c.width, c.height);
    ClusterLists& l = in.lists;
    if (l.clusters != g.count() || !l.counts) {
        // The shading pass reads the lists through a buffer texture, so they must fit its limit too.
        l.cap = clusterListCap(g.count(),
                               std::min<long long>(in.caps.maxStorageBlockBytes, 4LL * in.caps.maxTextureBufferTexels));
        l.counts = gl::Buffer::create(GL_SHADER_STORAGE_BUFFER, std::size_t(g.count()) * sizeof(GLuint), nullptr,
                                      GL_DYNAMIC_COPY, "cluster counts");
        l.lights = gl::Buffer::create(GL_SHADER_STORAGE_BUFFER,
                                      std::size_t(g.count()) * std::size_t(std::max(l.cap, 1)) * sizeof(GLuint),
                                      nullptr, GL_DYNAMIC_COPY, "cluster lights");
        l.list = gl::Texture::createBuffer(GL_R32UI, l.lights.id(), "cluster lights.tbo");
        l.clusters = g.count();
    }
    tileBinPass({in.bin, in.deferred.lights, in.deferred.gbuffer.depth, in.bins, in.caps},
                {c.view, c.projection, c.width, c.height, c.nearPlane, c.farPlane});
    gl::Program const& p = in.build;
    p.use();
    bindLights(p, in.deferred.lights);
    p.set("uBinCap", in.bins.cap);
    p.set("uInverseProjection", glm::inverse(c.projection));
    setGridUniforms(p, in, c, g);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_CLUSTER_LIGHTS, in.lists.lights.id());  // written here
    glDispatchCompute(GLuint(g.tilesX), GLuint(g.tilesY), 1);  // one work group per tile, a slice per invocation
    gl::countDispatch();
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_CLUSTER_LIGHTS, 0);
}

LightingOutput clusterShadePass(LightingClusteredInput const& in, LightingClusteredConfig const& c) {
    ClusterGrid const g = clusterGrid(c.width, c.height);
    gl::Program const& p = in.shade;
    p.use();
    bindDeferredInputs(p, in.deferred);
    setGridUniforms(p, in, c, g);
    p.set("uShade", c.shade ? 1 : 0);
    p.set("uWriteCoverage", c.coverage ? 1 : 0);
    // The tiles' sorted lists that clusterListsPass left in the bins, for clusters over their cap.
    p.set("uBinCap", in.bins.cap);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_TILE_BIN_COUNTS, in.bins.counts.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_TILE_BIN_LIGHTS, in.bins.lights.id());
    bindLightImages(in.hdr, in.specular, in.coverage);
    bindTextureUnit(slot::BIND_CLUSTER_LIST, GL_TEXTURE_BUFFER, in.lists.list.id());
    TileGrid const grid = tileGrid(c.width, c.height);
    glDispatchCompute(GLuint(grid.tilesX), GLuint(grid.tilesY), 1);
    gl::countDispatch();
    // Later passes read the images as textures and framebuffer attachments.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    unbindLightImages();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_CLUSTER_COUNTS, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_TILE_BIN_COUNTS, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_TILE_BIN_LIGHTS, 0);
    return {in.hdr};
}

}  // namespace gbl
