// model/viewer_fields.h: one entry per setting of ViewerState, each editing its own member, with
// its default inside its range; sessions write and read every entry under its key; copying a
// viewer's settings copies exactly the entries.
#include "model/viewer_fields.h"
#include "session/editor_session.h"
#include "session/session.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <functional>
#include <set>
#include <string>

using namespace gbl;
using namespace gbl::ui;

namespace {

// A value of `f` other than `now`, inside its range.
double otherValue(ViewerField const& f, double now) {
    switch (f.kind) {
        case ViewerFieldKind::Toggle:
            return now != 0.0 ? 0.0 : 1.0;
        case ViewerFieldKind::Choice:
            return double((int(now) + 1) % int(f.names.size()));
        case ViewerFieldKind::Flags:
            return now == 5.0 ? 10.0 : 5.0;
        case ViewerFieldKind::Mask:
            return now == 9.0 ? 6.0 : 9.0;
        case ViewerFieldKind::Number:
            break;
    }
    // Inside [min, max] and away from the default; the range fields keep min < max below.
    if (f.key == "zoom") return now == 4.0 ? 2.0 : 4.0;
    if (f.key == "center") return now == 0.25 ? 0.75 : 0.25;
    return now + 0.5;
}

ViewerState depthViewer() {
    return GBufferPanelState::defaultViewers()[std::size_t(ViewerKind::Depth)];
}

// Every member of ViewerState that is a setting, each changed from its default: each must be
// covered by an entry of the table (some entry reads a different value).
std::vector<std::pair<char const*, std::function<void(ViewerState&)>>> settingMembers() {
    return {
        {"channelMask", [](ViewerState& v) { v.channelMask = 0x2; }},
        {"rangeMin", [](ViewerState& v) { v.rangeMin = -3.0f; }},
        {"rangeMax", [](ViewerState& v) { v.rangeMax = 7.0f; }},
        {"autoFit", [](ViewerState& v) { v.autoFit = !v.autoFit; }},
        {"normalDisplay", [](ViewerState& v) { v.normalDisplay = NormalDisplay::Absolute; }},
        {"linearDepth", [](ViewerState& v) { v.linearDepth = !v.linearDepth; }},
        {"cameraClipPlanes", [](ViewerState& v) { v.cameraClipPlanes = !v.cameraClipPlanes; }},
        {"nearPlane", [](ViewerState& v) { v.nearPlane = 0.3f; }},
        {"farPlane", [](ViewerState& v) { v.farPlane = 30.0f; }},
        {"zoom", [](ViewerState& v) { v.zoom = 3.0f; }},
        {"center.x", [](ViewerState& v) { v.center.x = 0.2f; }},
        {"center.y", [](ViewerState& v) { v.center.y = 0.8f; }},
        {"showHistogram", [](ViewerState& v) { v.showHistogram = !v.showHistogram; }},
        {"showStencil", [](ViewerState& v) { v.showStencil = !v.showStencil; }},
        {"colormap", [](ViewerState& v) { v.colormap = Colormap::Viridis; }},
        {"overlays", [](ViewerState& v) { v.overlays = kOverlayNaN | kOverlayClip; }},
    };
}

TEST(ViewerFields, EverySettingMemberHasOneEntryEditingItsOwn) {
    // Fails to compile when ViewerState gains or loses a member. A setting gets an entry in
    // model/viewer_fields.cpp and a line in settingMembers(); a run-time fact of the viewer (what
    // it learnt from the image, a request to the loop, a drag in progress) gets neither. Then update
    // the names here.
    [[maybe_unused]] auto const& [kind, channelMask, rangeMin, rangeMax, autoFit, fitRequested, lastFitFrame,
                                  normalDisplay, linearDepth, cameraClipPlanes, nearPlane, farPlane, zoom, center,
                                  imageSize, showHistogram, showStencil, otherRange, colormap, overlays, picked, region,
                                  regionDragStart, regionRowsHeight, histogramDrag, percentileFitRequested,
                                  regionFitRequested, pinRequested, showDiff, diffMode, diffThreshold, sample] =
        ViewerState{};

    std::span<ViewerField const> const fields = viewerFields();
    ASSERT_EQ(fields.size(), settingMembers().size());
    ViewerState const base = depthViewer();
    for (auto const& [name, change] : settingMembers()) {
        ViewerState v = base;
        change(v);
        int differing = 0;
        for (ViewerField const& f : fields) differing += f.get(v) != f.get(base) ? 1 : 0;
        EXPECT_EQ(differing, 1) << name << " is read by " << differing << " entries of the table, not one";
    }

    std::set<std::pair<std::string_view, int>> keys;
    for (ViewerField const& f : fields) {
        EXPECT_TRUE(keys.insert({f.key, f.component}).second) << f.key << " is in the table twice";
        EXPECT_FALSE(f.help.empty()) << f.key << " has no help line";
        ViewerState v = base;
        double const other = otherValue(f, f.get(v));
        ASSERT_TRUE(f.accepts(other)) << f.key << ": the test's value " << other << " is out of range";
        f.set(v, other);
        EXPECT_EQ(f.get(v), double(float(other))) << f.key << " does not read back what it wrote";
        for (ViewerField const& g : fields) {
            if (&g != &f) {
                EXPECT_EQ(g.get(v), g.get(base)) << f.key << " also changed " << g.key;
            }
        }
    }
}

TEST(ViewerFields, DefaultsLieInTheirRanges) {
    for (ViewerState const& v : GBufferPanelState::defaultViewers())
        for (ViewerField const& f : viewerFields()) EXPECT_TRUE(f.accepts(f.get(v))) << f.key << " = " << f.get(v);
    for (ViewerField const& f : viewerFields()) {
        if (f.kind != ViewerFieldKind::Number) continue;
        EXPECT_FALSE(f.accepts(std::nan(""))) << f.key;
        EXPECT_FALSE(f.accepts(std::numeric_limits<double>::infinity())) << f.key;
    }
    ViewerField const* zoom = nullptr;
    for (ViewerField const& f : viewerFields())
        if (f.key == "zoom") zoom = &f;
    ASSERT_NE(zoom, nullptr);
    EXPECT_FALSE(zoom->accepts(0.5));
    EXPECT_FALSE(zoom->accepts(257.0));
}

// Each entry edited alone in the depth viewer of a session survives writing and reading, under its
// own key (the tool fields under "tools").
TEST(ViewerFields, SessionsWriteAndReadEveryEntryUnderItsKey) {
    std::size_t const depth = std::size_t(ViewerKind::Depth);
    for (ViewerField const& f : viewerFields()) {
        Session s;
        f.set(s.viewers[depth], otherValue(f, f.get(s.viewers[depth])));
        std::string const text = sessionToJson(s);
        nlohmann::json const j = nlohmann::json::parse(text);
        nlohmann::json const& viewer = j["viewers"]["depth"];
        EXPECT_TRUE(f.inTools ? viewer["tools"].contains(std::string(f.key)) : viewer.contains(std::string(f.key)))
            << f.key;
        SessionLoad const back = parseSession(text, "s.json");
        ASSERT_TRUE(back.session) << f.key << ": " << back.error;
        EXPECT_EQ(f.get(back.session->viewers[depth]), f.get(s.viewers[depth])) << f.key;
    }
    // The keys written are the table's, in its order.
    nlohmann::ordered_json const j = nlohmann::ordered_json::parse(sessionToJson(Session{}));
    std::vector<std::string_view> written;
    for (auto const& [key, value] : j["viewers"]["depth"].items()) written.push_back(key);
    std::vector<std::string> writtenCopy(written.begin(), written.end());
    std::vector<std::string> const table(viewerFileKeys().begin(), viewerFileKeys().end());
    EXPECT_EQ(writtenCopy, table);
}

TEST(ViewerFields, OutOfRangeValuesAreNamed) {
    nlohmann::json j = nlohmann::json::parse(sessionToJson(Session{}));
    j["viewers"]["normal"]["zoom"] = 300.0;
    SessionLoad const zoom = parseSession(j.dump(), "s.json");
    EXPECT_FALSE(zoom.session);
    EXPECT_NE(zoom.error.find("viewers.normal.zoom"), std::string::npos) << zoom.error;

    j = nlohmann::json::parse(sessionToJson(Session{}));
    j["viewers"]["normal"]["tools"]["overlays"] = {"nan", "sparkles"};
    SessionLoad const overlays = parseSession(j.dump(), "s.json");
    EXPECT_FALSE(overlays.session);
    EXPECT_NE(overlays.error.find("viewers.normal.tools.overlays[1]"), std::string::npos) << overlays.error;

    j = nlohmann::json::parse(sessionToJson(Session{}));
    j["viewers"]["albedo"]["tools"]["stencil"] = true;
    SessionLoad const stencil = parseSession(j.dump(), "s.json");
    EXPECT_FALSE(stencil.session);
    EXPECT_NE(stencil.error.find("viewers.albedo.tools.stencil"), std::string::npos) << stencil.error;

    j = nlohmann::json::parse(sessionToJson(Session{}));
    j["viewers"]["depth"]["center"] = {0.5, 1.5};
    SessionLoad const centre = parseSession(j.dump(), "s.json");
    EXPECT_FALSE(centre.session);
    EXPECT_NE(centre.error.find("viewers.depth.center[1]"), std::string::npos) << centre.error;
}

// Copying a viewer's settings copies every entry and nothing the viewer learnt at run time; the
// viewport's copy leaves zoom, pan and the linear switch it does not use.
TEST(ViewerFields, CopyingSettingsCopiesTheEntriesOnly) {
    ViewerState from = depthViewer();
    for (ViewerField const& f : viewerFields()) f.set(from, otherValue(f, f.get(from)));
    from.imageSize = glm::ivec2(640, 360);
    from.lastFitFrame = 12;

    ViewerState to = depthViewer();
    copyViewerSettings(from, to);
    for (ViewerField const& f : viewerFields()) EXPECT_EQ(f.get(to), f.get(from)) << f.key;
    EXPECT_EQ(to.imageSize, glm::ivec2(0));
    EXPECT_EQ(to.lastFitFrame, -1);

    ViewerState viewport = depthViewer();
    copyViewerSettings(from, viewport, /*viewport=*/true);
    for (ViewerField const& f : viewerFields())
        EXPECT_EQ(f.get(viewport), f.viewport ? f.get(from) : f.get(depthViewer())) << f.key;

    // The stencil is a depth viewer's only.
    ViewerState albedo = GBufferPanelState::defaultViewers()[std::size_t(ViewerKind::Albedo)];
    copyViewerSettings(from, albedo);
    EXPECT_FALSE(albedo.showStencil);
}

}  // namespace
