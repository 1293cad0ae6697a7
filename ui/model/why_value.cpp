// "Why this value": each mode's light test replayed on the CPU for one pixel.
#include "model/why_value.h"

#include "core/cluster_math.h"
#include "core/depth.h"
#include "core/light_math.h"
#include "core/light_volume_cone.h"
#include "core/light_volume_mesh.h"
#include "core/shading_cpu.h"
#include "core/spot_cull.h"
#include "core/tile_math.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gbl::ui {

namespace {

// The light volume is a polyhedron between the spheres of radius r and r * enclosingScale; the
// reasoning below takes the enclosing sphere for it (a pixel ray grazing the sphere between two
// vertices may miss the real mesh) and compares distances along the pixel's ray where the GPU
// compares quantised depths (ties at the surface can go either way).
struct VolumeHit {
    bool cameraInside = false;
    bool hits = false;  // the pixel's ray crosses the sphere
    float t0 = 0.0f;    // entry (front face), may be behind the eye
    float t1 = 0.0f;    // exit (back face)
};

VolumeHit hitVolume(glm::vec3 eye, glm::vec3 dir, glm::vec3 centre, float radius) {
    VolumeHit h;
    glm::vec3 const oc = eye - centre;
    float const b = glm::dot(oc, dir), c = glm::dot(oc, oc) - radius * radius;
    h.cameraInside = c < 0.0f;
    float const disc = b * b - c;
    if (disc < 0.0f) return h;
    float const s = std::sqrt(disc);
    h.hits = true;
    h.t0 = -b - s;
    h.t1 = -b + s;
    return h;
}

// A spot's cone volume: the ray clipped by every face plane of the very mesh the pass draws
// (convex), so entry and exit are exact.
VolumeHit hitCone(glm::vec3 eye, glm::vec3 dir, ConeVolume const& cone) {
    static ConeMesh const mesh = makeLightVolumeCone();
    VolumeHit h;
    float tMin = -std::numeric_limits<float>::infinity(), tMax = std::numeric_limits<float>::infinity();
    for (std::size_t t = 0; t + 2 < mesh.triangles.size(); t += 3) {
        glm::vec3 const a = coneVertexToWorld(cone, mesh.positions[mesh.triangles[t]]);
        glm::vec3 const b = coneVertexToWorld(cone, mesh.positions[mesh.triangles[t + 1]]);
        glm::vec3 const c = coneVertexToWorld(cone, mesh.positions[mesh.triangles[t + 2]]);
        glm::vec3 const n = glm::cross(b - a, c - a);                       // outward
        float const along = glm::dot(n, dir), room = glm::dot(n, a - eye);  // inside: t * along <= room
        if (along == 0.0f) {
            if (room < 0.0f) return h;
            continue;
        }
        if (along > 0.0f)
            tMax = std::min(tMax, room / along);
        else
            tMin = std::max(tMin, room / along);
    }
    if (!(tMin <= tMax)) return h;
    h.hits = true;
    h.t0 = tMin;
    h.t1 = tMax;
    h.cameraInside = tMin < 0.0f && tMax > 0.0f;
    return h;
}

// The range of ray distances between the clip planes, for a ray whose depth grows by `k` per unit.
struct ClipRange {
    float tNear = 0.0f, tFar = 0.0f;
    bool contains(float t) const { return t >= tNear && t <= tFar; }
};

struct Faces {
    int count = 0;
    std::string why;
};

// Cull back faces, depth test LESS: the front face must lie between the near plane and the surface.
Faces frontFacesPass(VolumeHit const& h, ClipRange const& clip, float tp) {
    if (h.cameraInside) return {0, "not evaluated: camera inside the volume, back faces culled"};
    if (h.t0 < clip.tNear) return {0, "not evaluated: front faces clipped by the near plane, back faces culled"};
    if (h.t0 >= tp) return {0, "not evaluated: surface in front of the volume (depth test)"};
    return {1, "front face in front of the surface"};
}

// Cull front faces, depth test GEQUAL: the back face must lie behind the surface, before the far plane.
Faces backFacesPass(VolumeHit const& h, ClipRange const& clip, float tp) {
    if (h.t1 < tp) return {0, "not evaluated: surface behind the volume (outside it), front faces culled"};
    if (h.t1 > clip.tFar) return {0, "not evaluated: back face past the far plane"};
    if (h.t1 < clip.tNear) return {0, "not evaluated: volume behind the near plane"};
    return {1, "back face behind the surface"};
}

Faces volumePass(PointLight const& light, float radius, WhyValueInput const& in, glm::vec3 dir, float tp,
                 ClipRange const& clip) {
    static float const scale = enclosingScale(makeLightVolumeSphere());
    if (radius <= 0.0f) return {0, "not evaluated: no volume (radius 0)"};
    float const enclosing = radius * scale;
    bool const cone = volumeShape(light) == VolumeShape::Cone;
    static float const radial = coneRadialScale(makeLightVolumeCone());
    ConeVolume const cv = coneVolume(light, radius, radial, in.settings.volumeScale);
    VolumeHit const h =
        cone ? hitCone(in.camera.position, dir, cv) : hitVolume(in.camera.position, dir, light.position, enclosing);
    if (!h.hits) return {0, "not evaluated: pixel outside the volume's footprint"};
    switch (in.settings.cull) {
        case CullMode::Back:
            return frontFacesPass(h, clip, tp);
        case CullMode::Front:
            return backFacesPass(h, clip, tp);
        case CullMode::None: {
            int const n = int(!h.cameraInside && clip.contains(h.t0)) + int(clip.contains(h.t1));
            return {n, n == 2   ? "both faces shaded (no culling, no depth test): counted twice"
                       : n == 1 ? "one face shaded (no culling, no depth test)"
                                : "not evaluated: both faces clipped"};
        }
        case CullMode::Flip: {
            float const aspect = float(in.frameSize.x) / float(std::max(in.frameSize.y, 1));
            float const corner =
                nearPlaneCornerDistance(glm::radians(in.camera.fovYDegrees), aspect, in.camera.nearPlane);
            bool const inside = cone ? coneMayContainCamera(in.camera.position, cv, corner)
                                     : volumeMayContainCamera(in.camera.position, light.position, enclosing, corner);
            Faces f = inside ? backFacesPass(h, clip, tp) : frontFacesPass(h, clip, tp);
            f.why = (inside ? "flip, camera may be inside: " : "flip, camera outside: ") + f.why;
            return f;
        }
        case CullMode::Stencil: {
            // Mark: +1 where the back face fails the depth test (behind the surface), -1 where the
            // front face does; shading keeps marks of exactly 1, once per pixel.
            bool const backMark = clip.contains(h.t1) && h.t1 >= tp;
            bool const frontMark = !h.cameraInside && clip.contains(h.t0) && h.t0 >= tp;
            if (backMark && !frontMark) return {1, "stencil: surface inside the volume"};
            if (frontMark) return {0, "not evaluated: stencil, surface in front of the volume"};
            if (h.t1 > clip.tFar) return {0, "not evaluated: stencil, back face past the far plane"};
            return {0, "not evaluated: stencil, surface behind the volume (outside it)"};
        }
    }
    return {0, "?"};
}

}  // namespace

std::vector<LightVerdict> explainPixel(WhyValueInput const& in, std::span<PointLight const> lights) {
    std::vector<LightVerdict> out;
    if (!in.sample.covered || in.frameSize.x <= 0 || in.frameSize.y <= 0) return out;
    ShadingInputs s;
    s.position = glm::vec3(in.sample.position);
    s.normal = glm::vec3(in.sample.normal);
    s.albedo = glm::vec3(in.sample.albedoSpec);
    s.specular = in.sample.albedoSpec.a;
    s.emissive = glm::vec3(in.sample.emissiveAo);
    s.occlusion = in.sample.emissiveAo.a;
    s.viewPosition = in.camera.position;
    shadingOf(in.settings, s);

    glm::vec3 const toSurface = s.position - in.camera.position;
    float const tp = glm::length(toSurface);
    glm::vec3 const dir = tp > 0.0f ? toSurface / tp : in.camera.forward();
    float const k = std::max(glm::dot(dir, in.camera.forward()), 1e-6f);
    ClipRange const clip{in.camera.nearPlane / k, in.camera.farPlane / k};

    // The pixel's tile, as the compute pass numbers it (bottom-left origin).
    glm::mat4 const view = in.camera.view();
    float const aspect = float(in.frameSize.x) / float(in.frameSize.y);
    TileGrid const grid = tileGrid(in.frameSize.x, in.frameSize.y);
    int const glY = in.frameSize.y - 1 - in.pixel.y;
    gbl::PixelRect const rect =
        tilePixelRect(grid, in.frameSize.x, in.frameSize.y, in.pixel.x / grid.tileSize, glY / grid.tileSize);
    TileFrustum const tile =
        tileFrustum(glm::inverse(in.camera.projection(aspect)), in.frameSize.x, in.frameSize.y, rect);
    float const ownDepth = linearDepth(in.sample.depth, in.camera.nearPlane, in.camera.farPlane);
    TileDepthBounds const bounds = in.tileBounds.value_or(TileDepthBounds{ownDepth, ownDepth});

    for (std::size_t i = 0; i < lights.size(); ++i) {
        PointLight const& light = lights[i];
        LightVerdict v;
        v.lightIndex = int(i);
        if (light.kind == LightKind::Directional) {
            // Global: every mode adds it once in its full-screen loop (no radius, volume or list).
            v.withinRadius = !validateLight(light);
            v.evaluated = v.withinRadius;
            v.evaluations = v.withinRadius ? 1 : 0;
            v.why = v.withinRadius ? "directional: the full-screen global-lights loop of every mode"
                                   : "directional, invalid: shades nothing";
            if (v.evaluated) v.added = shadeLightCpu(light, s).total();
            out.push_back(std::move(v));
            continue;
        }
        float const radius = lightRadius(light).radius;
        v.withinRadius = glm::distance(light.position, s.position) < radius;
        // prepass with volumes evaluates a light where the volumes mode would.
        switch (drawsLightVolumes(in.settings) ? LightingMode::Volumes : in.settings.mode) {
            case LightingMode::Quad:
                v.evaluations = 1;
                v.why = "quad: every light is tested at every pixel";
                break;
            case LightingMode::Forward:
                v.evaluations = 1;
                v.why = "forward: every light is tested at every fragment";
                break;
            case LightingMode::Prepass:
                v.evaluations = 1;
                v.why = "prepass: every light is tested at every pixel of the thin G-buffer";
                break;
            case LightingMode::Tiled:
            case LightingMode::ForwardPlus: {  // forward+ reads the same tiles' lists
                glm::vec3 const centreView = glm::vec3(view * glm::vec4(light.position, 1.0f));
                // Spots: then the cone against the sphere around the tile's depth range.
                glm::vec4 const tileSphere = frustumPieceSphere(
                    tileFarCorners(glm::inverse(in.camera.projection(aspect)), in.frameSize.x, in.frameSize.y, rect),
                    bounds.minDepth, bounds.maxDepth);
                bool const listed = radius > 0.0f &&
                                    sphereTouchesTile(tile, bounds.minDepth, bounds.maxDepth, centreView, radius) &&
                                    lightConeMayTouchSphere(light, view, glm::vec3(tileSphere), tileSphere.w);
                v.evaluations = listed ? 1 : 0;
                v.why = listed ? "in the tile's light list" : "not evaluated: not in the tile's light list";
                break;
            }
            case LightingMode::Clustered: {
                glm::vec3 const centreView = glm::vec3(view * glm::vec4(light.position, 1.0f));
                ClusterGrid const cg = clusterGrid(in.frameSize.x, in.frameSize.y);
                int const slice = clusterSlice(ownDepth, in.camera.nearPlane, in.camera.farPlane);
                ViewBox const box =
                    clusterViewBox(glm::inverse(in.camera.projection(aspect)), in.frameSize.x, in.frameSize.y, cg,
                                   in.pixel.x / kClusterTileSize, glY / kClusterTileSize, slice, in.camera.nearPlane,
                                   in.camera.farPlane);
                // The shader's margin (cluster_build.comp): a hair over the radius.
                // As cluster_build.comp: the tile's frustum (near to far) first, then the slice's box.
                bool const listed =
                    radius > 0.0f &&
                    sphereTouchesTile(tile, in.camera.nearPlane, in.camera.farPlane, centreView, radius) &&
                    sphereTouchesBox(centreView, radius * 1.0001f + 1e-4f, box) &&
                    lightConeMayTouchSphere(light, view, (box.lo + box.hi) * 0.5f, glm::length(box.hi - box.lo) * 0.5f);
                v.evaluations = listed ? 1 : 0;
                v.why = listed ? "in the cluster's light list" : "not evaluated: not in the cluster's light list";
                break;
            }
            case LightingMode::Volumes: {
                Faces const f = volumePass(light, radius, in, dir, tp, clip);
                v.evaluations = f.count;
                v.why = f.why;
                break;
            }
        }
        v.evaluated = v.evaluations > 0;
        // The shaders skip a light beyond its radius (its windowed attenuation is 0 there anyway),
        // except the learnopengl shading where the mode does not cut it (quad, forward).
        bool const reachesBeyond = s.model == ShadingModel::LearnOpenGl && !s.cutAtRadius && radius > 0.0f;
        if (v.evaluated && (v.withinRadius || reachesBeyond))
            v.added = shadeLightCpu(light, s).total() * float(v.evaluations);
        if (v.evaluated && !v.withinRadius)
            v.why += reachesBeyond ? "; outside its radius, lit all the same (learnopengl shading: no window)"
                                   : "; outside its radius, adds nothing";
        if (!v.evaluated && v.withinRadius) v.why += " (it would have reached the pixel)";
        out.push_back(std::move(v));
    }
    return out;
}

std::vector<int> lightsAroundEye(glm::vec3 eye, std::span<PointLight const> lights, float volumeScale) {
    static float const scale = enclosingScale(makeLightVolumeSphere());
    static float const radial = coneRadialScale(makeLightVolumeCone());
    std::vector<int> out;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        PointLight const& light = lights[i];
        if (light.kind == LightKind::Directional) continue;  // no volume
        float const radius = lightRadius(light).radius;
        if (radius <= 0.0f) continue;
        // Any ray from the eye starts inside a convex volume exactly when the eye is inside it.
        VolumeHit const h =
            volumeShape(light) == VolumeShape::Cone
                ? hitCone(eye, glm::vec3(0.0f, 0.0f, 1.0f), coneVolume(light, radius, radial, volumeScale))
                : hitVolume(eye, glm::vec3(0.0f, 0.0f, 1.0f), light.position, radius * scale * volumeScale);
        if (h.cameraInside) out.push_back(int(i));
    }
    return out;
}

std::optional<TileDepthBounds> tileDepthBounds(FloatImage const& depth, glm::ivec2 pixel, float nearPlane,
                                               float farPlane) {
    if (depth.width <= 0 || depth.height <= 0 || depth.channels < 1) return std::nullopt;
    TileGrid const grid = tileGrid(depth.width, depth.height);
    int const glY = depth.height - 1 - pixel.y;
    gbl::PixelRect const r =
        tilePixelRect(grid, depth.width, depth.height, pixel.x / grid.tileSize, glY / grid.tileSize);
    std::optional<TileDepthBounds> b;
    for (int y = r.y0; y < r.y1; ++y) {
        int const row = depth.height - 1 - y;  // the image's rows run top to bottom
        for (int x = r.x0; x < r.x1; ++x) {
            float const d = depth.at(x, row, 0);
            if (!(d < 1.0f)) continue;  // background
            float const v = linearDepth(d, nearPlane, farPlane);
            if (!b) b = TileDepthBounds{v, v};
            b->minDepth = std::min(b->minDepth, v);
            b->maxDepth = std::max(b->maxDepth, v);
        }
    }
    return b;
}

}  // namespace gbl::ui
