// The G-buffer layout table, its memory figures and the octahedral normal encoding on the CPU.
#include "core/gbuffer_layout.h"
#include "core/octahedral.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace gbl;

namespace {

// In double and through atan2: acos of a float dot product near 1 alone would be off by ~0.02 degrees.
double angleDegrees(glm::vec3 a, glm::vec3 b) {
    glm::dvec3 const da(a), db(b);
    return std::atan2(glm::length(glm::cross(da, db)), glm::dot(da, db)) * 180.0 / glm::pi<double>();
}

// Directions over the whole sphere (a Fibonacci spiral) plus the axes and the octahedron's folds,
// where the encoding's sign handling is most likely to be wrong.
std::vector<glm::vec3> sphereDirections(int n) {
    std::vector<glm::vec3> out;
    float const golden = glm::pi<float>() * (3.0f - std::sqrt(5.0f));
    for (int i = 0; i < n; ++i) {
        float const y = 1.0f - 2.0f * (float(i) + 0.5f) / float(n);
        float const r = std::sqrt(1.0f - y * y);
        out.push_back({r * std::cos(golden * float(i)), y, r * std::sin(golden * float(i))});
    }
    for (glm::vec3 v : {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, -1, 0),
                        glm::vec3(0, 0, 1), glm::vec3(0, 0, -1), glm::vec3(1, 1, -1), glm::vec3(-1, 1, -1),
                        glm::vec3(-1, -1, -1), glm::vec3(1, 0, -1), glm::vec3(0, -1, -0.001f)})
        out.push_back(glm::normalize(v));
    return out;
}

}  // namespace

TEST(GBufferLayoutTest, TableMatchesTheNamesAndTheIssuesByteBudgets) {
    ASSERT_EQ(kGBufferLayouts.size(), kGBufferLayoutNames.size());
    for (std::size_t i = 0; i < kGBufferLayouts.size(); ++i) EXPECT_EQ(kGBufferLayouts[i].name, kGBufferLayoutNames[i]);
    // classic: RGBA16F position 8 + RGBA16F normal 8 + RGBA8 4 + RGBA16F emissive_ao 8 +
    // DEPTH32F_STENCIL8 8 (a 64-bit texel).
    EXPECT_EQ(layoutBytesPerPixel(layoutDesc(GBufferLayout::Classic)), 36);
    // packed: the issue's budget is at most 12 bytes, RG16 4 + RGBA8 4 + DEPTH24_STENCIL8 4, with no
    // spare channel, so it stores no emissive/occlusion (docs/gbuffer_layouts.md).
    EXPECT_EQ(layoutBytesPerPixel(layoutDesc(GBufferLayout::Packed)), 12);
    EXPECT_LE(layoutBytesPerPixel(layoutDesc(GBufferLayout::Packed)), 12) << "issue 12's budget";
    // The teaching layouts keep an RGBA8 emissive_ao: 4 + 4 + 4 + 4.
    EXPECT_EQ(layoutBytesPerPixel(layoutDesc(GBufferLayout::Naive8)), 16);
    EXPECT_EQ(layoutBytesPerPixel(layoutDesc(GBufferLayout::Rgb10a2)), 16);
    EXPECT_TRUE(layoutDesc(GBufferLayout::Classic).storesPosition);
    EXPECT_FALSE(layoutDesc(GBufferLayout::Packed).storesPosition);
    EXPECT_EQ(colorAttachmentIndex(layoutDesc(GBufferLayout::Classic), GBufferSlot::AlbedoSpec), 2);
    EXPECT_EQ(colorAttachmentIndex(layoutDesc(GBufferLayout::Packed), GBufferSlot::AlbedoSpec), 1);
    EXPECT_EQ(colorAttachmentIndex(layoutDesc(GBufferLayout::Packed), GBufferSlot::Position), -1);
    EXPECT_EQ(colorAttachmentIndex(layoutDesc(GBufferLayout::Classic), GBufferSlot::Emissive), 3);
    EXPECT_EQ(colorAttachmentIndex(layoutDesc(GBufferLayout::Packed), GBufferSlot::Emissive), -1);
    EXPECT_EQ(colorAttachmentIndex(layoutDesc(GBufferLayout::Rgb10a2), GBufferSlot::Emissive), 2);
    EXPECT_EQ(layoutDesc(GBufferLayout::Packed).attachmentCount, 3);
    EXPECT_EQ(layoutDesc(GBufferLayout::Packed).depthFormat(), TexelFormat::Depth24Stencil8);
}

TEST(GBufferLayoutTest, MegabytesAtCommonSizes) {
    // 36 B x 1920 x 1080 = 74.6496 MB; 12 B x 3840 x 2160 = 99.5328 MB; 16 B x 3840 x 2160 =
    // 132.7104 MB (10^6 bytes).
    EXPECT_NEAR(layoutMegabytes(layoutDesc(GBufferLayout::Classic), 1920, 1080), 74.6496, 1e-9);
    EXPECT_NEAR(layoutMegabytes(layoutDesc(GBufferLayout::Packed), 3840, 2160), 99.5328, 1e-9);
    EXPECT_NEAR(layoutMegabytes(layoutDesc(GBufferLayout::Naive8), 3840, 2160), 132.7104, 1e-9);
    EXPECT_EQ(layoutMegabytes(layoutDesc(GBufferLayout::Packed), 0, 0), 0.0);
}

TEST(GBufferLayoutTest, ShaderDefinesFollowTheDescription) {
    EXPECT_TRUE(layoutShaderDefines(layoutDesc(GBufferLayout::Classic)).empty());
    EXPECT_EQ(layoutShaderDefines(layoutDesc(GBufferLayout::Packed)),
              (std::vector<std::string>{"GBUFFER_POSITION_FROM_DEPTH", "GBUFFER_NORMAL_OCTAHEDRAL",
                                        "GBUFFER_NO_EMISSIVE_AO"}));
    EXPECT_EQ(layoutShaderDefines(layoutDesc(GBufferLayout::Naive8)),
              (std::vector<std::string>{"GBUFFER_POSITION_FROM_DEPTH", "GBUFFER_NORMAL_BIASED"}));
}

TEST(GBufferLayoutTest, OnlyALayoutWithoutEmissiveAoCarriesANote) {
    EXPECT_EQ(layoutOmissionNote(layoutDesc(GBufferLayout::Packed)),
              "packed: no room for emissive and occlusion in 12 bytes; emission and AO are not shown");
    for (GBufferLayout l : {GBufferLayout::Classic, GBufferLayout::Naive8, GBufferLayout::Rgb10a2}) {
        EXPECT_TRUE(storesEmissiveAo(layoutDesc(l))) << layoutDesc(l).name;
        EXPECT_EQ(layoutOmissionNote(layoutDesc(l)), "") << layoutDesc(l).name;
    }
    EXPECT_FALSE(storesEmissiveAo(layoutDesc(GBufferLayout::Packed)));
}

TEST(OctahedralTest, UnquantizedRoundTripIsExact) {
    for (glm::vec3 n : sphereDirections(4000)) {
        glm::vec2 const e = octEncode(n);
        EXPECT_LE(std::max(std::abs(e.x), std::abs(e.y)), 1.0f) << "the code fills the square [-1, 1]^2";
        EXPECT_LT(angleDegrees(octDecode(e), n), 1e-4) << n.x << " " << n.y << " " << n.z;
    }
}

TEST(OctahedralTest, SixteenBitRoundTripIsWithinAHundredthOfADegree) {
    // 16 bits per component over [-1, 1] is a step of 3.05e-5; on the octahedron that moves the
    // decoded direction by at most about 2 x 3.05e-5 / (1/sqrt(3)) rad ~ 0.006 degrees in the worst
    // corner, far less at the poles. Stated bound: 0.01 degrees, and the mean well below it.
    double maxAngle = 0.0, sum = 0.0;
    auto const dirs = sphereDirections(20000);
    for (glm::vec3 n : dirs) {
        double const a = angleDegrees(octDecode(quantizeSnormAsUnorm16(octEncode(n))), n);
        maxAngle = std::max(maxAngle, a);
        sum += a;
    }
    EXPECT_LT(maxAngle, 0.01);
    EXPECT_LT(sum / double(dirs.size()), 0.005);
    EXPECT_GT(maxAngle, 0.0) << "quantization should move some direction: the test would not see a coarser format";
}

TEST(OctahedralTest, EightBitPerComponentWouldBeCoarse) {
    // The same directions quantized to 8 bits per octahedral component: the error the lecture warns
    // about (about 0.5 degrees and more), showing the 16-bit bound above is not trivially met.
    double maxAngle = 0.0;
    for (glm::vec3 n : sphereDirections(5000)) {
        glm::vec2 const u = glm::round((octEncode(n) * 0.5f + 0.5f) * 255.0f) / 255.0f;
        maxAngle = std::max(maxAngle, angleDegrees(octDecode(u * 2.0f - 1.0f), n));
    }
    EXPECT_GT(maxAngle, 0.3);
}
