// Light binning pass.
#include "passes/tile_bins.h"
#include "gl/draw_count.h"

#include "gl/shader_bindings.h"
#include "passes/shading_inputs.h"

#include <algorithm>

namespace gbl {

namespace {

void clearCounts(gl::Buffer const& counts) {
    GLuint const zero = 0;
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, counts.id());
    glClearBufferData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

}  // namespace

void tileBinPass(TileBinInput const& in, TileBinConfig const& c) {
    TileGrid const g = tileGrid(c.width, c.height);
    TileBins& b = in.bins;
    if (b.tiles != g.count() || !b.counts) {
        b.cap = tileBinCap(g.count(), in.caps.maxStorageBlockBytes);
        b.counts = gl::Buffer::create(GL_SHADER_STORAGE_BUFFER, std::size_t(g.count()) * sizeof(GLuint), nullptr,
                                      GL_DYNAMIC_COPY, "tile bin counts");
        b.lights = gl::Buffer::create(GL_SHADER_STORAGE_BUFFER,
                                      std::size_t(g.count()) * std::size_t(std::max(b.cap, 1)) * sizeof(GLuint),
                                      nullptr, GL_DYNAMIC_COPY, "tile bin lights");
        b.blendedCounts = gl::Buffer{};
        b.blendedLights = gl::Buffer{};
        b.depth = gl::Buffer::create(GL_SHADER_STORAGE_BUFFER, std::size_t(g.count()) * 2 * sizeof(GLfloat), nullptr,
                                     GL_DYNAMIC_COPY, "tile depth ranges");
        b.tiles = g.count();
    }
    if (c.blendedLists && !b.blendedCounts) {
        b.blendedCounts = gl::Buffer::create(GL_SHADER_STORAGE_BUFFER, std::size_t(g.count()) * sizeof(GLuint), nullptr,
                                             GL_DYNAMIC_COPY, "tile bin counts, blended surfaces");
        b.blendedLights = gl::Buffer::create(GL_SHADER_STORAGE_BUFFER,
                                             std::size_t(g.count()) * std::size_t(std::max(b.cap, 1)) * sizeof(GLuint),
                                             nullptr, GL_DYNAMIC_COPY, "tile bin lights, blended surfaces");
    }
    clearCounts(b.counts);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_TILE_BIN_COUNTS, b.counts.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_TILE_BIN_LIGHTS, b.lights.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_TILE_DEPTH, b.depth.id());

    gl::Program const& d = in.programs.depth;
    d.use();
    bindTextureUnit(slot::BIND_DEPTH, GL_TEXTURE_2D, in.depth.id());
    glUniform2i(d.uniform("uScreenSize"), c.width, c.height);
    d.set("uNear", c.nearPlane);
    d.set("uFar", c.farPlane);
    glDispatchCompute(GLuint(g.tilesX), GLuint(g.tilesY), 1);
    gl::countDispatch();
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    gl::Program const& p = in.programs.bin;
    p.use();
    bindLights(p, in.lights);
    p.set("uView", c.view);
    p.set("uProjection", c.projection);
    glUniform2i(p.uniform("uScreenSize"), c.width, c.height);
    glUniform2i(p.uniform("uTiles"), g.tilesX, g.tilesY);
    p.set("uBinCap", b.cap);
    p.set("uNear", c.nearPlane);
    p.set("uFar", c.farPlane);
    p.set("uFromNear", 0);
    auto const dispatch = [&] {
        if (in.lights.count > 0) {
            glDispatchCompute(GLuint((in.lights.count + 63) / 64), 1, 1);
            gl::countDispatch();
        }
    };
    dispatch();
    if (c.blendedLists) {  // the same lights again into the blended surfaces' lists
        clearCounts(b.blendedCounts);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_TILE_BIN_COUNTS, b.blendedCounts.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_TILE_BIN_LIGHTS, b.blendedLights.id());
        p.set("uFromNear", 1);
        dispatch();
        // Left bound for the list pass that follows, as documented: the opaque lists.
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_TILE_BIN_COUNTS, b.counts.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_TILE_BIN_LIGHTS, b.lights.id());
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_TILE_DEPTH, 0);
}

}  // namespace gbl
