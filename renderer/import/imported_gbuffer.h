// A foreign G-buffer in memory: the manifest's images read (image/image_io.h or raw), turned right way
// up, checked for consistent sizes and conventions, and decoded to world space.
#pragma once

#include "image/image_io.h"  // SampleStorage
#include "import/gbuffer_manifest.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gbl {

// One attachment as read: the manifest's channels of its file, rows top to bottom.
struct ImportedImage {
    std::string field;  // "normal", "albedo", ...
    std::string path;
    SampleStorage storage = SampleStorage::Float;
    int channels = 0;           // the selected channels
    std::vector<float> values;  // width * height * channels
    float at(std::size_t pixel, int c) const { return values[pixel * std::size_t(channels) + std::size_t(c)]; }
};

// Smallest step between stored values near 1 (8/16-bit: one level; half/float: one ulp at 1).
double storageStep(SampleStorage storage);
char const* storageName(SampleStorage storage);

struct ImportedGBuffer {
    int width = 0;
    int height = 0;
    GBufferManifest manifest;
    std::optional<CameraMatrices> camera;  // the manifest's, with its projection for this size
    // The attachments as read, in manifest order (position, normal, albedo, specular, emissive,
    // occlusion, depth, lit).
    std::vector<ImportedImage> images;
    // Decoded per pixel (empty when the manifest has no such attachment):
    std::vector<glm::vec3> position;  // world space, stored or rebuilt from depth
    std::vector<glm::vec3> normal;    // world space, decoded, not renormalised
    std::vector<glm::vec3> albedo;    // linear
    std::vector<float> specular;      //
    std::vector<glm::vec3> emissive;  // linear emitted radiance, times emissive.scale
    std::vector<float> occlusion;     // ambient occlusion, [0, 1]
    std::vector<float> viewDistance;  // from depth: distance along -z in view space
    std::vector<glm::vec3> lit;       //
    // 1 where a background marker says nothing was drawn: depth at its clear value, a coverage
    // channel at 0, a normal stored as all zeros, or a position of exactly (0, 0, 0).
    std::vector<std::uint8_t> background;
    // 1 where any attachment holds NaN or Inf at the pixel.
    std::vector<std::uint8_t> nonFinite;

    std::size_t pixelCount() const { return std::size_t(width) * std::size_t(height); }
    ImportedImage const* image(std::string_view field) const;
};

struct GBufferLoad {
    std::optional<ImportedGBuffer> gbuffer;
    std::string error;  // one sentence naming the manifest field when gbuffer is empty
};

// Reads every image of the manifest and decodes it. Refused, with the field named: a missing or
// unreadable file, a channel the file lacks, images of different sizes, a raw file of the wrong
// length, depth values the declared convention cannot hold, negative emission, occlusion outside [0, 1].
GBufferLoad loadGBuffer(GBufferManifest const& manifest);

// The world-space point behind pixel (x, y) at view distance `distance` (pixel centres, row 0 at
// the top), through the camera's inverse projection and view.
glm::vec3 worldFromDistance(CameraMatrices const& camera, glm::mat4 const& inverseView,
                            glm::mat4 const& inverseProjection, int width, int height, float x, float y,
                            float distance);

// View distance of a stored depth value under a convention (window [0, 1], NDC [-1, 1], linear).
float distanceFromDepth(float depth, DepthConvention convention, float nearPlane, float farPlane);

}  // namespace gbl
