// Loading a foreign G-buffer: images through image/image_io.h or as raw
// samples, then decoding.
#include "import/imported_gbuffer.h"

#include "import/gbuffer_files.h"
#include "import/gbuffer_probe.h"

#include "core/depth.h"
#include "core/octahedral.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <future>
#include <limits>
#include <map>
#include <sstream>

namespace gbl {

namespace {

using detail::ChannelRange;
using detail::FileImage;
using detail::readFile;
using detail::sizeText;

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// An image's first three channels per pixel as linear colour: sRGB decoded when so declared, then scaled.
std::vector<glm::vec3> linearRgb(ImportedImage const& im, std::size_t pixels, ColorEncoding encoding, float scale) {
    std::vector<glm::vec3> out(pixels);
    for (std::size_t p = 0; p < pixels; ++p) {
        glm::vec3 v(im.at(p, 0), im.at(p, 1), im.at(p, 2));
        if (encoding == ColorEncoding::Srgb) v = glm::vec3(srgbToLinear(v.x), srgbToLinear(v.y), srgbToLinear(v.z));
        out[p] = v * scale;
    }
    return out;
}

// A sentence naming the field when finite values of `im` fall outside [lo, hi] (NaN and Inf are the
// nan_inf check's), with a count and the worst value: "occlusion holds values outside [0, 1] in
// FILE at 12 pixels (e.g. 37.2): is that channel ambient occlusion?".
std::optional<std::string> outsideRange(ImportedImage const& im, float lo, float hi, std::string const& what,
                                        std::string const& hint) {
    std::size_t pixels = 0;
    float worst = 0.0f;
    std::size_t const n = im.values.size() / std::size_t(std::max(im.channels, 1));
    for (std::size_t p = 0; p < n; ++p) {
        bool bad = false;
        for (int c = 0; c < im.channels; ++c) {
            float const v = im.at(p, c);
            if (!std::isfinite(v) || (v >= lo - 1e-6f && v <= hi + 1e-6f)) continue;
            bad = true;
            if (std::abs(v) > std::abs(worst)) worst = v;
        }
        pixels += bad;
    }
    if (pixels == 0) return std::nullopt;
    std::ostringstream msg;
    msg << what << " " << im.path << " at " << pixels << " pixel" << (pixels == 1 ? "" : "s") << " (e.g. " << worst
        << "): " << hint;
    return msg.str();
}

bool finite3(glm::vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

double storageStep(SampleStorage s) {
    switch (s) {
        case SampleStorage::Uint8:
            return 1.0 / 255.0;
        case SampleStorage::Uint16:
            return 1.0 / 65535.0;
        case SampleStorage::Half:
            return 1.0 / 1024.0;  // 10 mantissa bits: the step just above 1
        case SampleStorage::Float:
        case SampleStorage::Other:
            return 1.0 / 8388608.0;
    }
    return 0.0;
}

char const* storageName(SampleStorage s) {
    switch (s) {
        case SampleStorage::Uint8:
            return "8-bit unsigned";
        case SampleStorage::Uint16:
            return "16-bit unsigned";
        case SampleStorage::Half:
            return "16-bit float";
        case SampleStorage::Float:
            return "32-bit float";
        case SampleStorage::Other:
            return "other";
    }
    return "other";
}

ImportedImage const* ImportedGBuffer::image(std::string_view field) const {
    for (auto const& i : images)
        if (i.field == field) return &i;
    return nullptr;
}

float distanceFromDepth(float d, DepthConvention convention, float n, float f) {
    switch (convention) {
        case DepthConvention::Window:
            return linearDepth(d, n, f);
        case DepthConvention::Ndc:
            return linearDepth(0.5f * d + 0.5f, n, f);
        case DepthConvention::Linear:
            return d;
    }
    return d;
}

glm::vec3 worldFromDistance(CameraMatrices const&, glm::mat4 const& inverseView, glm::mat4 const& inverseProjection,
                            int width, int height, float x, float y, float distance) {
    float const ndcX = (x + 0.5f) / float(width) * 2.0f - 1.0f;
    float const ndcY = 1.0f - (y + 0.5f) / float(height) * 2.0f;
    glm::vec4 v = inverseProjection * glm::vec4(ndcX, ndcY, -1.0f, 1.0f);
    glm::vec3 p = glm::vec3(v) / v.w;
    p *= distance / -p.z;  // scale the near-plane point to the distance along -z
    return glm::vec3(inverseView * glm::vec4(p, 1.0f));
}

GBufferLoad loadGBuffer(GBufferManifest const& m) {
    GBufferLoad out;
    std::string const label = m.label + ": ";
    auto refuse = [&](std::string const& message) {
        out.error = label + message;
        return out;
    };
    ImportedGBuffer g;
    g.manifest = m;

    // Every attachment named, in order; one read per distinct file (albedo and specular often share one).
    std::vector<ImageRef const*> refs;
    if (m.position) refs.push_back(&m.position->image);
    refs.push_back(&m.normal.image);
    if (m.albedo) refs.push_back(&m.albedo->image);
    if (m.specular) refs.push_back(&*m.specular);
    if (m.emissive) refs.push_back(&m.emissive->image);
    if (m.occlusion) refs.push_back(&*m.occlusion);
    if (m.depth) refs.push_back(&m.depth->image);
    if (m.lit) refs.push_back(&*m.lit);
    // Every file is looked at before any is decoded (gbuffer_probe.h).
    if (auto why = probeGBufferFiles(refs)) return refuse(*why);
    // The distinct files are decoded side by side (EXR decoding is nearly all of a load).
    std::map<std::string, ChannelRange> ranges;
    for (ImageRef const* ref : refs) {
        auto [it, fresh] = ranges.try_emplace(ref->path, ChannelRange{99, -1});
        for (int c : ref->channels) {
            it->second.first = std::min(it->second.first, c);
            it->second.last = std::max(it->second.last, c);
        }
    }
#ifdef __EMSCRIPTEN__
    auto const policy = std::launch::deferred;  // no threads in the page
#else
    auto const policy = std::launch::async;
#endif
    struct Read {
        std::optional<FileImage> image;
        std::string error;
    };
    std::map<std::string, std::future<Read>> reads;
    for (ImageRef const* ref : refs)
        if (!reads.count(ref->path))
            reads.emplace(ref->path, std::async(policy, [ref, range = ranges[ref->path]] {
                              Read r;
                              r.image = readFile(*ref, range, &r.error);
                              return r;
                          }));
    std::map<std::string, FileImage> files;
    for (ImageRef const* ref : refs) {
        if (files.count(ref->path)) continue;
        Read r = reads.at(ref->path).get();
        if (!r.image) return refuse(r.error);
        files.emplace(ref->path, std::move(*r.image));
    }
    std::string firstField;
    for (ImageRef const* ref : refs) {
        FileImage const& f = files.at(ref->path);
        if (g.width == 0) {
            g.width = f.width;
            g.height = f.height;
            firstField = ref->field;
        } else if (f.width != g.width || f.height != g.height) {
            return refuse(ref->field + ".file " + ref->path + " is " + sizeText(f.width, f.height) + " but " +
                          firstField + " is " + sizeText(g.width, g.height) +
                          ": every attachment must have the frame's size");
        }
        for (int c : ref->channels)
            if (c >= f.fileChannels)
                return refuse(ref->field + " asks for channel " + std::string(1, "rgba"[c]) + " but " + ref->path +
                              " has " + std::to_string(f.fileChannels) + " channel" + (f.fileChannels == 1 ? "" : "s"));
        ImportedImage im;
        im.field = ref->field;
        im.path = ref->path;
        im.storage = f.storage;
        im.channels = int(ref->channels.size());
        std::size_t const n = std::size_t(f.width) * std::size_t(f.height);
        im.values.resize(n * ref->channels.size());
        for (int y = 0; y < f.height; ++y) {
            int const srcY = m.flipY ? f.height - 1 - y : y;
            for (int x = 0; x < f.width; ++x) {
                std::size_t const src =
                    (std::size_t(srcY) * std::size_t(f.width) + std::size_t(x)) * std::size_t(f.channels);
                std::size_t const dst = (std::size_t(y) * std::size_t(f.width) + std::size_t(x)) * ref->channels.size();
                for (std::size_t c = 0; c < ref->channels.size(); ++c)
                    im.values[dst + c] = f.pixels[src + std::size_t(ref->channels[c] - f.firstChannel)];
            }
        }
        g.images.push_back(std::move(im));
    }
    std::size_t const n = g.pixelCount();
    if (m.camera) g.camera = cameraForSize(*m.camera, g.width, g.height);

    // NaN and Inf anywhere: such pixels are marked and left out of the other checks.
    g.nonFinite.assign(n, 0);
    for (ImportedImage const& im : g.images)
        for (std::size_t p = 0; p < n; ++p)
            for (int c = 0; c < im.channels; ++c)
                if (!std::isfinite(im.at(p, c))) g.nonFinite[p] = 1;

    g.background.assign(n, 0);
    if (m.depth) {
        ImportedImage const& d = *g.image("depth");
        DepthSpec const& s = *m.depth;
        float lo = 0.0f, hi = 1.0f;
        if (s.convention == DepthConvention::Ndc) lo = -1.0f;
        std::size_t outside = 0;
        float worst = 0.0f;
        g.viewDistance.resize(n);
        for (std::size_t p = 0; p < n; ++p) {
            float const v = d.values[p];
            if (!std::isfinite(v)) continue;
            bool const bad = s.convention == DepthConvention::Linear ? v < 0.0f : (v < lo - 1e-6f || v > hi + 1e-6f);
            if (bad) {
                ++outside;
                if (std::abs(v) > std::abs(worst)) worst = v;
            }
            // Cleared depth: the far value of a window/NDC buffer, or far (or 0) in a linear one.
            bool const clear = s.convention == DepthConvention::Linear ? (v <= 0.0f || v >= s.farPlane * (1.0f - 1e-6f))
                                                                       : v >= 1.0f - 1e-7f;
            if (clear) g.background[p] = 1;
            g.viewDistance[p] = distanceFromDepth(v, s.convention, s.nearPlane, s.farPlane);
        }
        if (outside > 0) {
            std::ostringstream msg;
            msg << "depth.convention is " << kDepthConventionNames[std::size_t(s.convention)] << " but " << outside
                << " pixel" << (outside == 1 ? "" : "s") << " of " << d.path << " hold values it cannot ("
                << (s.convention == DepthConvention::Linear ? "negative"
                                                            : "outside [" + std::to_string(int(lo)) + ", 1]")
                << ", e.g. " << worst << ")"
                << (s.convention != DepthConvention::Linear && worst > 1.0f
                        ? ": linear view distances? set \"convention\": \"linear\""
                        : "");
            return refuse(msg.str());
        }
    }
    if (m.position) {
        ImportedImage const& pi = *g.image("position");
        g.position.resize(n);
        glm::mat4 const invView = g.camera ? glm::inverse(g.camera->view) : glm::mat4(1.0f);
        if (m.position->space == Space::View && !g.camera)
            return refuse("position.space is view, which needs the camera to place positions in the world");
        for (std::size_t p = 0; p < n; ++p) {
            glm::vec3 v(pi.at(p, 0), pi.at(p, 1), pi.at(p, 2));
            if (v == glm::vec3(0.0f)) g.background[p] = 1;  // cleared to 0 (LearnOpenGL's gPosition)
            // The coverage channel rides along as a fourth channel (gbuffer_manifest.cpp).
            if (m.position->coverageChannel && pi.at(p, 3) == 0.0f) g.background[p] = 1;
            if (m.position->space == Space::View) v = glm::vec3(invView * glm::vec4(v, 1.0f));
            g.position[p] = v;
        }
    }
    {
        ImportedImage const& ni = *g.image("normal");
        g.normal.resize(n);
        glm::mat3 const toWorld = g.camera ? glm::mat3(glm::inverse(g.camera->view)) : glm::mat3(1.0f);
        if (m.normal.space == Space::View && !g.camera)
            return refuse("normal.space is view, which needs the camera to turn normals into world space");
        for (std::size_t p = 0; p < n; ++p) {
            glm::vec3 nv;
            if (m.normal.encoding == NormalEncoding::Octahedral) {
                nv = octDecode(glm::vec2(ni.at(p, 0), ni.at(p, 1)));
            } else {
                glm::vec3 const s(ni.at(p, 0), ni.at(p, 1), ni.at(p, 2));
                if (s == glm::vec3(0.0f)) g.background[p] = 1;  // a cleared normal target
                nv = m.normal.encoding == NormalEncoding::Biased ? s * 2.0f - 1.0f : s;
            }
            if (m.normal.space == Space::View) nv = toWorld * nv;
            g.normal[p] = nv;
        }
    }
    if (m.positionFromDepth) {
        glm::mat4 const invView = glm::inverse(g.camera->view), invProj = glm::inverse(g.camera->projection);
        g.position.resize(n);
        for (int y = 0; y < g.height; ++y)
            for (int x = 0; x < g.width; ++x) {
                std::size_t const p = std::size_t(y) * std::size_t(g.width) + std::size_t(x);
                g.position[p] = worldFromDistance(*g.camera, invView, invProj, g.width, g.height, float(x), float(y),
                                                  g.viewDistance[p]);
            }
    }
    if (m.albedo) g.albedo = linearRgb(*g.image("albedo"), n, m.albedo->encoding, 1.0f);
    if (m.specular) g.specular = g.image("specular")->values;
    if (m.emissive) {
        ImportedImage const& e = *g.image("emissive");
        g.emissive = linearRgb(e, n, m.emissive->encoding, m.emissive->scale);
        if (auto err =
                outsideRange(e, 0.0f, std::numeric_limits<float>::infinity(), "emissive holds negative values in",
                             "emission only adds light (a signed or biased encoding?)"))
            return refuse(*err);
    }
    if (m.occlusion) {
        ImportedImage const& o = *g.image("occlusion");
        g.occlusion = o.values;
        if (auto err = outsideRange(o, 0.0f, 1.0f, "occlusion holds values outside [0, 1] in",
                                    "is that channel ambient occlusion (1 = unoccluded)?"))
            return refuse(*err);
    }
    if (m.lit) {
        ImportedImage const& l = *g.image("lit");
        g.lit.resize(n);
        for (std::size_t p = 0; p < n; ++p) g.lit[p] = glm::vec3(l.at(p, 0), l.at(p, 1), l.at(p, 2));
    }
    for (std::size_t p = 0; p < n; ++p)
        if (!g.position.empty() && !finite3(g.position[p])) g.nonFinite[p] = 1;
    out.gbuffer = std::move(g);
    return out;
}

}  // namespace gbl
