// The view-projection from world positions and their pixels: a normalised direct linear transform (the
// 3x4 that maps a position to (x w, y w, w) in normalised device coordinates, solved by least squares as
// the eigenvector of the smallest eigenvalue of the normal equations), then split into a rigid view and
// a frustum, with the depth rows from the depth attachment where there is one.
#include "capture/camera_solve.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace gbl::capture {

namespace {

using Mat12 = std::array<std::array<double, 12>, 12>;

struct Sample {
    glm::dvec3 world;
    glm::dvec2 ndc;
    int x = 0, y = 0;
};

bool drawn(FloatImage const& img, int x, int y) {
    return img.at(x, y, 0) != 0.0f || img.at(x, y, 1) != 0.0f || img.at(x, y, 2) != 0.0f;
}

glm::dvec2 pixelCentreNdc(int x, int y, int w, int h) {
    return {2.0 * (x + 0.5) / w - 1.0, 1.0 - 2.0 * (y + 0.5) / h};  // rows top to bottom
}

// At most `limit` drawn pixels, spread evenly over the image.
std::vector<Sample> samplesOf(FloatImage const& img, std::size_t limit) {
    std::size_t count = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) count += drawn(img, x, y) ? 1 : 0;
    std::size_t const stride = std::max<std::size_t>(1, count / limit);
    std::vector<Sample> out;
    std::size_t i = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            if (!drawn(img, x, y) || i++ % stride != 0) continue;
            glm::dvec3 const p(img.at(x, y, 0), img.at(x, y, 1), img.at(x, y, 2));
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
            out.push_back({p, pixelCentreNdc(x, y, img.width, img.height), x, y});
        }
    return out;
}

// The unit eigenvector of the smallest eigenvalue of a symmetric matrix (cyclic Jacobi rotations).
std::array<double, 12> smallestEigenvector(Mat12 a) {
    Mat12 v{};
    for (int i = 0; i < 12; ++i) v[i][i] = 1.0;
    for (int sweep = 0; sweep < 60; ++sweep) {
        double off = 0.0;
        for (int p = 0; p < 12; ++p)
            for (int q = p + 1; q < 12; ++q) off += a[p][q] * a[p][q];
        if (off < 1e-30) break;
        for (int p = 0; p < 12; ++p)
            for (int q = p + 1; q < 12; ++q) {
                if (std::abs(a[p][q]) < 1e-300) continue;
                double const theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                double const t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                double const c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                for (int k = 0; k < 12; ++k) {
                    double const akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 12; ++k) {
                    double const apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 12; ++k) {
                    double const vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
    }
    int best = 0;
    for (int i = 1; i < 12; ++i)
        if (a[i][i] < a[best][best]) best = i;
    std::array<double, 12> out{};
    for (int k = 0; k < 12; ++k) out[std::size_t(k)] = v[k][best];
    return out;
}

using Row = glm::dvec4;  // a row of the 3x4: (x, y, z, translation)

double apply(Row const& r, glm::dvec3 const& p) {
    return r.x * p.x + r.y * p.y + r.z * p.z + r.w;
}

}  // namespace

Reprojection reprojectionError(FloatImage const& position, glm::mat4 const& viewProj) {
    Reprojection r;
    double sum = 0.0;
    for (int y = 0; y < position.height; ++y)
        for (int x = 0; x < position.width; ++x) {
            if (!drawn(position, x, y)) continue;
            glm::vec4 const clip =
                viewProj * glm::vec4(position.at(x, y, 0), position.at(x, y, 1), position.at(x, y, 2), 1.0f);
            double e = 1e9;  // behind the camera: as far off as can be
            if (clip.w > 0.0f) {
                double const px = (double(clip.x) / clip.w * 0.5 + 0.5) * position.width;
                double const py = (0.5 - double(clip.y) / clip.w * 0.5) * position.height;
                e = std::hypot(px - (x + 0.5), py - (y + 0.5));
            }
            sum += e * e;
            r.max = std::max(r.max, e);
            ++r.samples;
        }
    r.rms = r.samples ? std::sqrt(sum / double(r.samples)) : 0.0;
    return r;
}

std::optional<SolvedCamera> solveCameraFromPositions(FloatImage const& position, FloatImage const* depth,
                                                     std::string* why) {
    if (position.channels < 3 || position.width < 2 || position.height < 2) {
        *why = "the position attachment has fewer than three channels";
        return std::nullopt;
    }
    std::vector<Sample> const samples = samplesOf(position, 40000);
    if (samples.size() < 64) {
        *why = "the position attachment has " + std::to_string(samples.size()) + " drawn pixels, too few to solve";
        return std::nullopt;
    }
    // Normalisation: positions centred with a mean distance of sqrt(3), pixels centred with sqrt(2).
    glm::dvec3 c(0.0);
    glm::dvec2 cu(0.0);
    for (Sample const& s : samples) c += s.world, cu += s.ndc;
    c /= double(samples.size());
    cu /= double(samples.size());
    double k = 0.0, ku = 0.0;
    for (Sample const& s : samples) k += glm::length(s.world - c), ku += glm::length(s.ndc - cu);
    k = std::sqrt(3.0) * double(samples.size()) / std::max(k, 1e-12);
    ku = std::sqrt(2.0) * double(samples.size()) / std::max(ku, 1e-12);
    Mat12 n{};
    for (Sample const& s : samples) {
        glm::dvec3 const p = (s.world - c) * k;
        glm::dvec2 const u = (s.ndc - cu) * ku;
        double const X[4] = {p.x, p.y, p.z, 1.0};
        for (int eq = 0; eq < 2; ++eq) {
            double row[12] = {};
            for (int j = 0; j < 4; ++j) {
                row[eq * 4 + j] = X[j];
                row[8 + j] = -(eq == 0 ? u.x : u.y) * X[j];
            }
            for (int i = 0; i < 12; ++i)
                for (int j = 0; j < 12; ++j) n[i][j] += row[i] * row[j];
        }
    }
    std::array<double, 12> const h = smallestEigenvector(n);
    // Undo the normalisations: P = U^-1 P' T, T(X) = k (X - c), U(u) = ku (u - cu).
    auto denormalise = [&](int r) {
        Row const a(h[std::size_t(r * 4)], h[std::size_t(r * 4 + 1)], h[std::size_t(r * 4 + 2)],
                    h[std::size_t(r * 4 + 3)]);
        return Row(a.x * k, a.y * k, a.z * k, a.w - k * (a.x * c.x + a.y * c.y + a.z * c.z));
    };
    Row const a0 = denormalise(0), a1 = denormalise(1), a3 = denormalise(2);
    Row r0 = a0 / ku + cu.x * a3, r1 = a1 / ku + cu.y * a3, r3 = a3;
    // The positions are in front: w > 0 at their centre.
    if (apply(r3, c) < 0.0) r0 = -r0, r1 = -r1, r3 = -r3;
    // Gram-Schmidt from the bottom row: M = K R with K upper triangular, the skew dropped.
    glm::dvec3 const m0(r0), m1(r1), m2(r3);
    double const s = glm::length(m2);
    if (s < 1e-12) {
        *why = "the positions do not determine a perspective camera";
        return std::nullopt;
    }
    glm::dvec3 const back = m2 / s;  // minus the view's z axis
    double const p12 = glm::dot(m1, back);
    glm::dvec3 const u1 = m1 - p12 * back;
    double const p11 = glm::length(u1);
    glm::dvec3 const axisY = u1 / p11;
    double const p01 = glm::dot(m0, axisY), p02 = glm::dot(m0, back);
    glm::dvec3 const u0 = m0 - p01 * axisY - p02 * back;
    double const p00 = glm::length(u0);
    if (p00 < 1e-12 || p11 < 1e-12) {
        *why = "the positions do not determine a perspective camera";
        return std::nullopt;
    }
    glm::dvec3 const axisX = u0 / p00, axisZ = -back;
    if (glm::dot(glm::cross(axisX, axisY), axisZ) < 0.0) {
        *why = "the positions fit only a mirrored camera (are the rows upside down?)";
        return std::nullopt;
    }
    // Translation: K t = the 3x4's last column (without the skew, as the view will have it).
    double const tz = r3.w / s;  // along `back`
    double const ty = (r1.w - p12 * tz) / p11;
    double const tx = (r0.w - p01 * ty - p02 * tz) / p00;
    SolvedCamera out;
    glm::dvec3 const axes[3] = {axisX, axisY, axisZ};
    double const t[3] = {tx, ty, -tz};
    out.view = glm::mat4(1.0f);
    for (int r = 0; r < 3; ++r) {
        for (int col = 0; col < 3; ++col) out.view[col][r] = float(axes[r][col]);
        out.view[3][r] = float(t[r]);
    }
    // View depths of the samples (-z), for near and far.
    std::vector<double> depths;
    depths.reserve(samples.size());
    for (Sample const& smp : samples) depths.push_back(glm::dot(back, smp.world) + tz);
    auto const [lo, hi] = std::minmax_element(depths.begin(), depths.end());
    if (*lo <= 0.0) {
        *why = "some positions lie behind the solved camera";
        return std::nullopt;
    }
    // Depth rows: ndc z (-z_v) = A z_v + B. From the depth attachment by least squares, else near and far
    // bracketing the positions.
    double A = 0.0, B = 0.0;
    if (depth && depth->width == position.width && depth->height == position.height && depth->channels >= 1) {
        double szz = 0, sz = 0, n1 = 0, szb = 0, sb = 0;
        for (std::size_t i = 0; i < samples.size(); ++i) {
            double const d = depth->at(samples[i].x, samples[i].y, 0);
            if (!(d > 0.0 && d < 1.0)) continue;
            double const zv = -depths[i], rhs = (2.0 * d - 1.0) * depths[i];
            szz += zv * zv, sz += zv, n1 += 1.0, szb += zv * rhs, sb += rhs;
        }
        double const det = szz * n1 - sz * sz;
        if (n1 >= 16 && std::abs(det) > 1e-12) {
            A = (szb * n1 - sz * sb) / det;
            B = (szz * sb - sz * szb) / det;
            double const nearPlane = B / (A - 1.0), farPlane = B / (A + 1.0);
            out.depthFitted = nearPlane > 0.0 && farPlane > nearPlane;
        }
    }
    if (!out.depthFitted) {
        double const nearPlane = *lo * 0.5, farPlane = *hi * 2.0;
        A = -(farPlane + nearPlane) / (farPlane - nearPlane);
        B = -2.0 * farPlane * nearPlane / (farPlane - nearPlane);
    }
    out.projection = glm::mat4(0.0f);
    out.projection[0][0] = float(p00 / s);
    out.projection[2][0] = float(-p02 / s);
    out.projection[1][1] = float(p11 / s);
    out.projection[2][1] = float(-p12 / s);
    out.projection[2][2] = float(A);
    out.projection[3][2] = float(B);
    out.projection[2][3] = -1.0f;
    Reprojection const e = reprojectionError(position, out.projection * out.view);
    out.rmsPixels = e.rms;
    out.maxPixels = e.max;
    out.samples = samples.size();
    return out;
}

}  // namespace gbl::capture
