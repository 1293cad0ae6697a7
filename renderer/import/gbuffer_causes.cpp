// Causes proven from the data: which target a "normal" really is, its encoding, and the camera's fit.
#include "import/gbuffer_causes.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace gbl {

namespace {

GBufferFinding make(ImportedGBuffer const& g, char const* check, char const* attachment, std::vector<std::uint8_t> mask,
                    std::string cause) {
    GBufferFinding f;
    f.check = check;
    f.attachment = attachment;
    f.pixels = std::size_t(std::count(mask.begin(), mask.end(), std::uint8_t(1)));
    f.share = g.pixelCount() ? double(f.pixels) / double(g.pixelCount()) : 0.0;
    f.cause = std::move(cause);
    f.mask = std::move(mask);
    return f;
}

glm::vec3 raw3(ImportedImage const& im, std::size_t p) {
    return {im.at(p, 0), im.at(p, 1), im.at(p, 2)};
}

// Pearson correlation of two images' first three channels over the geometry (0 when either is flat).
double correlation(ImportedImage const& a, ImportedImage const& b, std::vector<std::uint8_t> const& geometry) {
    double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0, n = 0;
    for (std::size_t p = 0; p < geometry.size(); ++p) {
        if (!geometry[p]) continue;
        for (int c = 0; c < 3; ++c) {
            double const x = a.at(p, c), y = b.at(p, c);
            sa += x, sb += y, saa += x * x, sbb += y * y, sab += x * y, n += 1;
        }
    }
    if (n < 2) return 0;
    double const va = saa - sa * sa / n, vb = sbb - sb * sb / n;
    if (va <= 1e-12 * n || vb <= 1e-12 * n) return 0;
    return (sab - sa * sb / n) / std::sqrt(va * vb);
}

// What the normal attachment's stored values say about it; true when a cause was named.
bool normalIdentity(ImportedGBuffer const& g, std::vector<std::uint8_t> const& geometry, GBufferCheckReport& r) {
    GBufferManifest const& m = g.manifest;
    ImportedImage const* ni = g.image("normal");
    if (!ni || ni->channels < 3 || m.normal.encoding == NormalEncoding::Octahedral) return false;
    double const tol = std::max(0.03, 3.0 * storageStep(ni->storage));
    std::size_t drawn = 0, nonNegative = 0, unitRaw = 0, unitBiased = 0;
    for (std::size_t p = 0; p < geometry.size(); ++p) {
        if (!geometry[p]) continue;
        glm::vec3 const v = raw3(*ni, p);
        ++drawn;
        nonNegative += v.x >= 0 && v.y >= 0 && v.z >= 0;
        unitRaw += std::abs(glm::length(v) - 1.0f) < tol;
        unitBiased += std::abs(glm::length(2.0f * v - 1.0f) - 1.0f) < 2.0 * tol;
    }
    if (drawn == 0) return false;
    auto share = [&](std::size_t k) { return double(k) / double(drawn); };
    std::vector<std::uint8_t> mask(geometry.begin(), geometry.end());
    if (m.normal.encoding == NormalEncoding::Biased && share(unitRaw) >= 0.9 && share(nonNegative) < 0.99) {
        r.findings.push_back(
            make(g, "normal_encoding", "normal", std::move(mask),
                 "The normals are stored as float (unit length, with negative components) but declared "
                 "biased: set normal.encoding to float."));
        return true;
    }
    if (m.normal.encoding == NormalEncoding::Float && share(unitBiased) >= 0.9 && share(unitRaw) < 0.5) {
        r.findings.push_back(make(g, "normal_encoding", "normal", std::move(mask),
                                  "The normals are stored biased (0.5·n + 0.5: unit length once decoded) but declared "
                                  "float: set normal.encoding to biased."));
        return true;
    }
    if (share(nonNegative) < 0.99 || share(unitRaw) >= 0.5 || share(unitBiased) >= 0.5) return false;
    // Not a normal in either encoding: which other attachment does it follow?
    for (ImportedImage const& other : g.images) {
        if (other.field == "normal" || other.channels < 3) continue;
        if (other.path == ni->path && other.field != "normal") {
            // The same file: the same target by construction.
        } else if (correlation(*ni, other, geometry) < 0.95) {
            continue;
        }
        r.findings.push_back(make(g, "normal_wrong_attachment", "normal", std::move(mask),
                                  "This looks like the " + other.field +
                                      " target (all components >= 0, far from unit "
                                      "length, and following " +
                                      other.field +
                                      " pixel for pixel): is the lighting "
                                      "pass's sampler bound to the wrong attachment?"));
        return true;
    }
    return false;
}

// The share of geometry pixels whose stored position projects through `m` to its own pixel (rows
// mirrored when `flip`), within a pixel.
double reprojectionFit(ImportedGBuffer const& g, ImportedImage const& pos, std::vector<std::uint8_t> const& geometry,
                       glm::mat4 const& m, bool flip, std::vector<std::uint8_t>* misses) {
    std::size_t drawn = 0, fit = 0;
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x) {
            std::size_t const p = std::size_t(y) * std::size_t(g.width) + std::size_t(x);
            if (!geometry[p]) continue;
            ++drawn;
            glm::vec4 const c = m * glm::vec4(raw3(pos, p), 1.0f);
            bool ok = false;
            if (c.w > 0.0f) {
                float const px = (c.x / c.w * 0.5f + 0.5f) * float(g.width);
                float const py = (0.5f - c.y / c.w * 0.5f) * float(g.height);
                float const row = float(flip ? g.height - 1 - y : y) + 0.5f;
                ok = std::abs(px - (float(x) + 0.5f)) <= 1.0f && std::abs(py - row) <= 1.0f;
            }
            fit += ok;
            if (misses) (*misses)[p] = !ok;
        }
    return drawn ? double(fit) / double(drawn) : 1.0;
}

void reprojection(ImportedGBuffer const& g, std::vector<std::uint8_t> const& geometry, GBufferCheckReport& r) {
    GBufferManifest const& m = g.manifest;
    ImportedImage const* pos = g.image("position");
    if (!g.camera || !m.position || !pos || pos->channels < 3) return;
    for (auto const& f : r.findings)
        if (f.check == "position_depth_mismatch") return;  // depth already named the cause
    glm::mat4 const view = g.camera->view, proj = g.camera->projection;
    bool const world = m.position->space == Space::World;
    glm::mat4 const declared = world ? proj * view : proj;
    std::vector<std::uint8_t> misses(geometry.size(), 0);
    double const fit = reprojectionFit(g, *pos, geometry, declared, false, &misses);
    if (fit >= 0.9) return;
    struct Hypothesis {
        glm::mat4 matrix;
        bool flip;
        std::string cause;
    };
    std::string const declaredSpace = world ? "world" : "view", otherSpace = world ? "view" : "world";
    Hypothesis const hypotheses[] = {
        {declared, true,
         "The rows are upside down: the positions project to their own pixels only with the rows turned over, so "
         "flip_y is the other way."},
        {world ? proj : proj * view, false,
         "These positions are in " + otherSpace + " space, not " + declaredSpace + ": set position.space to " +
             otherSpace + "."},
        {world ? glm::transpose(proj) * glm::transpose(view) : glm::transpose(proj), false,
         "The camera's matrices fit the positions only when transposed: matrix_layout is the other one."},
    };
    for (Hypothesis const& h : hypotheses)
        if (reprojectionFit(g, *pos, geometry, h.matrix, h.flip, nullptr) >= 0.9) {
            r.findings.push_back(make(g, "reprojection", "position", std::move(misses), h.cause));
            return;
        }
    // No hypothesis fits: nothing is said. A position written off the pixel centres, or a jittered
    // camera, misses by design, and this check names causes it can prove, not suspicions.
}

// Normals against the surfaces the positions describe: the cross product of each pixel's neighbours'
// positions. Normals that match those only in the other space are named so; true when they were.
bool normalSpace(ImportedGBuffer const& g, std::vector<std::uint8_t> const& geometry, GBufferCheckReport& r) {
    GBufferManifest const& m = g.manifest;
    if (!g.camera || g.position.empty() || g.normal.empty()) return false;
    glm::mat3 const viewRotation(g.camera->view), worldFromView = glm::transpose(viewRotation);
    bool const declaredView = m.normal.space == Space::View;
    std::size_t tested = 0, fitDeclared = 0, fitOther = 0;
    std::vector<std::uint8_t> mask(geometry.size(), 0);
    auto at = [&](int x, int y) { return std::size_t(y) * std::size_t(g.width) + std::size_t(x); };
    for (int y = 0; y + 1 < g.height; ++y)
        for (int x = 0; x + 1 < g.width; ++x) {
            std::size_t const p = at(x, y), px = at(x + 1, y), py = at(x, y + 1);
            if (!geometry[p] || !geometry[px] || !geometry[py]) continue;
            glm::vec3 const dx = g.position[px] - g.position[p], dy = g.position[py] - g.position[p];
            glm::vec3 const c = glm::cross(dx, dy);
            float const len = glm::length(c);
            // Neighbours on one surface only: an edge between two surfaces gives no plane.
            if (len < 1e-12f || glm::length(g.normal[p]) < 0.5f) continue;
            glm::vec3 const geo = c / len, n = glm::normalize(g.normal[p]);
            // The declared decode is g.normal; the other space's is the stored vector read the other way.
            glm::vec3 const other = glm::normalize(declaredView ? viewRotation * n : worldFromView * n);
            ++tested;
            bool const d = std::abs(glm::dot(geo, n)) > 0.95f, o = std::abs(glm::dot(geo, other)) > 0.95f;
            fitDeclared += d;
            fitOther += o;
            mask[p] = !d;
        }
    if (tested < 16 || double(fitDeclared) >= 0.5 * double(tested) || double(fitOther) < 0.9 * double(tested))
        return false;
    std::string const declared = declaredView ? "view" : "world", other = declaredView ? "world" : "view";
    r.findings.push_back(make(g, "normal_space", "normal", std::move(mask),
                              "These normals are in " + other + " space, not " + declared +
                                  ": they match the surfaces the positions describe only read as " + other +
                                  "; set normal.space to " + other + "."));
    return true;
}

}  // namespace

void addProvenCauses(ImportedGBuffer const& g, std::vector<std::uint8_t> const& geometry, GBufferCheckReport& r) {
    if (normalIdentity(g, geometry, r)) {
        // The symptoms the cause explains would only point elsewhere ("normalise", "normal matrix").
        std::erase_if(r.findings, [](GBufferFinding const& f) {
            return f.check == "normal_not_unit" || f.check == "normal_facing_away" || f.check == "normal_unbiased";
        });
    }
    reprojection(g, geometry, r);
    if (normalSpace(g, geometry, r))
        std::erase_if(r.findings, [](GBufferFinding const& f) { return f.check == "normal_facing_away"; });
}

}  // namespace gbl
