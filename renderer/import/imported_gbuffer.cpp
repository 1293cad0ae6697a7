// Loading a foreign G-buffer: images through OpenImageIO (stb_image in the browser) or as raw
// samples, then decoding.
#include "import/imported_gbuffer.h"

#include "core/depth.h"
#include "core/octahedral.h"

#ifdef __EMSCRIPTEN__
#include <stb_image.h>
#else
#include <OpenImageIO/imageio.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

namespace gbl {

namespace {

struct FileImage {
    int width = 0;
    int height = 0;
    int channels = 0;
    SampleStorage storage = SampleStorage::Float;
    std::vector<float> pixels;
};

// IEEE 754 binary16 to float (raw half files; OpenImageIO converts its own formats).
float halfToFloat(std::uint16_t h) {
    std::uint32_t const sign = std::uint32_t(h & 0x8000u) << 16;
    std::uint32_t exp = (h >> 10) & 0x1fu;
    std::uint32_t mant = h & 0x3ffu;
    std::uint32_t bits;
    if (exp == 0) {
        if (mant == 0) {
            bits = sign;
        } else {  // subnormal: normalise
            exp = 127 - 15 + 1;
            while (!(mant & 0x400u)) {
                mant <<= 1;
                --exp;
            }
            bits = sign | (exp << 23) | ((mant & 0x3ffu) << 13);
        }
    } else if (exp == 31) {
        bits = sign | 0x7f800000u | (mant << 13);
    } else {
        bits = sign | ((exp + 127 - 15) << 23) | (mant << 13);
    }
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}

std::string sizeText(int w, int h) {
    return std::to_string(w) + "x" + std::to_string(h);
}

std::optional<FileImage> readRaw(ImageRef const& ref, std::string* error) {
    RawFormat const& f = *ref.raw;
    std::ifstream in(ref.path, std::ios::binary);
    if (!in) {
        *error = ref.field + ".file " + ref.path + " cannot be read (no such file, or no permission)";
        return std::nullopt;
    }
    std::ostringstream s;
    s << in.rdbuf();
    std::string const bytes = s.str();
    std::size_t const bytesPer = f.type == RawType::Float ? 4 : f.type == RawType::Half ? 2 : 1;
    std::size_t const samples = std::size_t(f.width) * std::size_t(f.height) * std::size_t(f.channels);
    if (bytes.size() != samples * bytesPer) {
        *error = ref.field + ".raw does not match " + ref.path + ": " + sizeText(f.width, f.height) + " with " +
                 std::to_string(f.channels) + " " + std::string(kRawTypeNames[std::size_t(f.type)]) +
                 " channels needs " + std::to_string(samples * bytesPer) + " bytes, the file holds " +
                 std::to_string(bytes.size());
        return std::nullopt;
    }
    FileImage img{f.width, f.height, f.channels, SampleStorage::Float, std::vector<float>(samples)};
    for (std::size_t i = 0; i < samples; ++i) {
        if (f.type == RawType::Float) {
            std::memcpy(&img.pixels[i], bytes.data() + i * 4, 4);
        } else if (f.type == RawType::Half) {
            std::uint16_t h;
            std::memcpy(&h, bytes.data() + i * 2, 2);
            img.pixels[i] = halfToFloat(h);
        } else {
            img.pixels[i] = float(static_cast<unsigned char>(bytes[i])) / 255.0f;
        }
    }
    img.storage = f.type == RawType::Float  ? SampleStorage::Float
                  : f.type == RawType::Half ? SampleStorage::Half
                                            : SampleStorage::Uint8;
    return img;
}

#ifdef __EMSCRIPTEN__
// The browser build reads PNG, JPEG and HDR files (8 or 16 bits, or float) through stb_image; EXR
// needs OpenImageIO and is refused with that reason.
std::optional<FileImage> readFile(ImageRef const& ref, std::string* error) {
    if (ref.raw) return readRaw(ref, error);
    char const* path = ref.path.c_str();
    FileImage img;
    if (!stbi_info(path, &img.width, &img.height, &img.channels)) {
        std::ifstream probe(ref.path);
        std::string const reason = !probe                       ? "no such file, or no permission"
                                   : ref.path.ends_with(".exr") ? "EXR needs OpenImageIO, which the browser build lacks"
                                                                : stbi_failure_reason();
        *error = ref.field + ".file " + ref.path + " cannot be read (" + reason + ")";
        return std::nullopt;
    }
    if (img.width <= 0 || img.height <= 0 || img.channels <= 0 ||
        std::size_t(img.width) * std::size_t(img.height) > (std::size_t(1) << 28)) {
        *error = ref.field + ".file " + ref.path + " has no usable size (" + sizeText(img.width, img.height) + ")";
        return std::nullopt;
    }
    std::size_t const count = std::size_t(img.width) * std::size_t(img.height) * std::size_t(img.channels);
    img.pixels.resize(count);
    int w = 0, h = 0, c = 0;
    if (stbi_is_hdr(path)) {
        img.storage = SampleStorage::Float;
        float* data = stbi_loadf(path, &w, &h, &c, 0);
        if (data) std::copy(data, data + count, img.pixels.begin());
        stbi_image_free(data);
        if (!data) {
            *error = ref.field + ".file " + ref.path + " cannot be read (" + stbi_failure_reason() + ")";
            return std::nullopt;
        }
        return img;
    }
    bool const sixteen = stbi_is_16_bit(path) != 0;
    img.storage = sixteen ? SampleStorage::Uint16 : SampleStorage::Uint8;
    std::uint16_t* data = stbi_load_16(path, &w, &h, &c, 0);
    if (!data) {
        *error = ref.field + ".file " + ref.path + " cannot be read (" + stbi_failure_reason() + ")";
        return std::nullopt;
    }
    for (std::size_t i = 0; i < count; ++i) img.pixels[i] = float(data[i]) / 65535.0f;
    stbi_image_free(data);
    return img;
}
#else
std::optional<FileImage> readFile(ImageRef const& ref, std::string* error) {
    if (ref.raw) return readRaw(ref, error);
    // Alpha is data here (LearnOpenGL's gAlbedoSpec.png keeps specular in it), never coverage: without
    // this OpenImageIO premultiplies a PNG's colour by its alpha and the albedo comes out darkened.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(ref.path, &config);
    if (!in) {
        std::string reason = OIIO::geterror();
        std::ifstream probe(ref.path);
        if (!probe) reason = "no such file, or no permission";
        *error = ref.field + ".file " + ref.path + " cannot be read (" + reason + ")";
        return std::nullopt;
    }
    OIIO::ImageSpec const& spec = in->spec();
    FileImage img;
    img.width = spec.width;
    img.height = spec.height;
    img.channels = spec.nchannels;
    OIIO::TypeDesc const t = spec.format;
    img.storage = t == OIIO::TypeDesc::UINT8    ? SampleStorage::Uint8
                  : t == OIIO::TypeDesc::UINT16 ? SampleStorage::Uint16
                  : t == OIIO::TypeDesc::HALF   ? SampleStorage::Half
                  : t == OIIO::TypeDesc::FLOAT  ? SampleStorage::Float
                                                : SampleStorage::Other;
    if (img.width <= 0 || img.height <= 0 || img.channels <= 0 ||
        std::size_t(img.width) * std::size_t(img.height) > (std::size_t(1) << 28)) {
        *error = ref.field + ".file " + ref.path + " has no usable size (" + sizeText(img.width, img.height) + ")";
        return std::nullopt;
    }
    img.pixels.resize(std::size_t(img.width) * std::size_t(img.height) * std::size_t(img.channels));
    if (!in->read_image(0, 0, 0, img.channels, OIIO::TypeDesc::FLOAT, img.pixels.data())) {
        *error = ref.field + ".file " + ref.path + " cannot be read (" + in->geterror() + ")";
        return std::nullopt;
    }
    return img;
}
#endif

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
    std::map<std::string, FileImage> files;
    std::string firstField;
    for (ImageRef const* ref : refs) {
        auto it = files.find(ref->path);
        if (it == files.end()) {
            std::string error;
            auto img = readFile(*ref, &error);
            if (!img) return refuse(error);
            it = files.emplace(ref->path, std::move(*img)).first;
        }
        FileImage const& f = it->second;
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
            if (c >= f.channels)
                return refuse(ref->field + " asks for channel " + std::string(1, "rgba"[c]) + " but " + ref->path +
                              " has " + std::to_string(f.channels) + " channel" + (f.channels == 1 ? "" : "s"));
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
                    im.values[dst + c] = f.pixels[src + std::size_t(ref->channels[c])];
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
