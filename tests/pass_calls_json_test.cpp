// stats.json's "calls" (core/json_fields.h, passCallsJson): each pass's draws, dispatches and
// triangles, a pass that ran twice summed, and FrameStats' totals over its passes.
#include "core/json_fields.h"

#include <gtest/gtest.h>

using namespace gbl;

TEST(PassCallsJson, EachPassHasItsDrawsDispatchesAndTriangles) {
    FrameStats st;
    st.calls = {{"prepass_geometry", 12, 0, 4096},
                {"lighting", 3, 0, 1 + 2 * 480},
                {"prepass_shading", 12, 0, 4096},
                {"light_lists", 0, 2, 0},
                {"display", 1, 0, 1},
                {"display", 1, 0, 1}};  // a pass run twice (a view): summed under its one name
    nlohmann::json const j = json_fields::passCallsJson(st.calls);
    ASSERT_EQ(j.size(), 5u);
    EXPECT_EQ(j["prepass_geometry"]["triangles"], 4096);
    EXPECT_EQ(j["prepass_geometry"]["draws"], 12);
    EXPECT_EQ(j["prepass_shading"]["triangles"], j["prepass_geometry"]["triangles"]);
    EXPECT_EQ(j["lighting"]["triangles"], 961);
    EXPECT_EQ(j["light_lists"]["dispatches"], 2);
    EXPECT_EQ(j["light_lists"]["triangles"], 0);
    EXPECT_EQ(j["display"]["draws"], 2);
    EXPECT_EQ(j["display"]["triangles"], 2);
    // The totals stats.json writes as triangles_drawn (and the Stats window shows): the passes' sum.
    EXPECT_EQ(st.triangles(), 4096u + 961u + 4096u + 2u);
    EXPECT_EQ(st.draws(), 12u + 3u + 12u + 2u);
    std::uint64_t sum = 0;
    for (auto const& [name, entry] : j.items()) sum += entry["triangles"].get<std::uint64_t>();
    EXPECT_EQ(sum, st.triangles());
    EXPECT_TRUE(json_fields::passCallsJson({}).empty());
}
