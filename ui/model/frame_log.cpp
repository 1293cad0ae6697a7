// JSON lines of the frame log, written without a JSON library: flat values and string arrays.
#include "model/frame_log.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace gbl::ui {

namespace {

std::string quoted(std::string const& s) {
    std::string out = "\"";
    for (char c : s) {
        unsigned char const u = static_cast<unsigned char>(c);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (u < 0x20) {
            char esc[8];
            std::snprintf(esc, sizeof esc, "\\u%04x", u);
            out += esc;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4f", v);
    return text;
}

std::string strings(std::vector<std::string> const& items) {
    std::string out = "[";
    // Appended in two steps: `"," + quoted(...)` makes a temporary whose insert at the front GCC 12's
    // -Wrestrict misreads as an overlapping copy inside std::string (a false positive at -O3).
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (i) out += ',';
        out += quoted(items[i]);
    }
    return out + "]";
}

}  // namespace

std::string frameLogJson(FrameLogLine const& l) {
    std::string out = "{\"frame\":" + std::to_string(l.frame);
    out += ",\"rendered\":" + std::string(l.rendered ? "true" : "false");
    out += ",\"renderReason\":" + quoted(l.renderReason);
    out += ",\"frameMs\":" + number(l.frameMs);
    out += ",\"camera\":[" + number(l.camera.x) + "," + number(l.camera.y) + "," + number(l.camera.z) + "]";
    out += ",\"cameraAngles\":[" + number(l.cameraAngles.x) + "," + number(l.cameraAngles.y) + "]";
    out += ",\"selectedLight\":" + std::to_string(l.selectedLight);
    out += ",\"textInput\":" + std::string(l.textInput ? "true" : "false");
    out += ",\"viewportHovered\":" + std::string(l.viewportHovered ? "true" : "false");
    out += ",\"viewport\":[" + number(l.viewport.x) + "," + number(l.viewport.y) + "," + number(l.viewport.z) + "," +
           number(l.viewport.w) + "]";
    // Appended piece by piece, as strings() is (GCC 12's -Wrestrict false positive).
    auto appendRect = [&](std::string& a, glm::vec4 r) {
        for (int c = 0; c < 4; ++c) {
            if (c) a += ',';
            a += number(r[c]);
        }
    };
    auto rect = [&](glm::vec4 r) {
        std::string a = "[";
        appendRect(a, r);
        return a + "]";
    };
    // Rectangles as one flat array of numbers, four per rectangle.
    auto flatRects = [&](std::vector<glm::vec4> const& rs) {
        std::string a = "[";
        for (std::size_t i = 0; i < rs.size(); ++i) {
            if (i) a += ',';
            appendRect(a, rs[i]);
        }
        return a + "]";
    };
    out += ",\"viewerImages\":" + flatRects(l.viewerImages);
    out += ",\"accumulate\":" + std::to_string(l.accumulate);
    out += ",\"scrubber\":" + rect(l.scrubber);
    out += ",\"abToggle\":" + rect(l.abToggle);
    out += ",\"pinLit\":" + rect(l.pinLit);
    out += ",\"litDiff\":" + rect(l.litDiff);
    out += ",\"abDivider\":" + number(l.abDivider) + ",\"abEvaluations\":[";
    for (std::size_t i = 0; i < l.abEvaluations.size(); ++i) out += (i ? "," : "") + std::to_string(l.abEvaluations[i]);
    out += "]";
    out += ",\"pickable\":[";
    for (std::size_t i = 0; i < l.pickable.size(); ++i)
        out += (i ? ",[" : "[") + std::to_string(l.pickable[i].index) + "," + number(l.pickable[i].window.x) + "," +
               number(l.pickable[i].window.y) + "]";
    out += "]";
    out += ",\"events\":" + strings(l.events);
    out += ",\"actions\":" + strings(l.actions);
    out += ",\"clipped\":" + strings(l.clipped);
    if (l.sessionPath) out += ",\"session\":" + quoted(*l.sessionPath);
    out += ",\"lesson\":" + quoted(l.lesson) + ",\"lessonButtons\":[";
    for (std::size_t i = 0; i < l.lessonButtons.size(); ++i)
        out += (i ? "," : "") + number(l.lessonButtons[i].x) + "," + number(l.lessonButtons[i].y);
    out += "],\"lessonMark\":[";
    for (std::size_t i = 0; i < l.lessonMark.size(); ++i) {
        char v[32];
        std::snprintf(v, sizeof v, "%.6g", double(l.lessonMark[i]));
        out += (i ? "," : "") + std::string(v);
    }
    out += "],\"lessonPrediction\":" + quoted(l.lessonPrediction);
    out += std::string(",\"lessonAnswer\":") + (l.lessonAnswer ? "true" : "false");
    out += ",\"lessonTasks\":" + quoted(l.lessonTasks);
    out += std::string(",\"presentation\":") + (l.presentation ? "true" : "false") +
           ",\"presentationCaption\":" + rect(l.presentationCaption) +
           ",\"presentationItem\":" + rect(l.presentationItem);
    out += ",\"lessonLines\":" + number(l.lessonLines) + ",\"lessonsWindow\":" + rect(l.lessonsWindow) +
           ",\"lessonHints\":" + std::to_string(l.lessonHints);
    out += std::string(",\"lessonGlossary\":") + (l.lessonGlossary ? "true" : "false");
    out += ",\"lessonGlossaryTerm\":" + quoted(l.lessonGlossaryTerm);
    out += ",\"courseRows\":" + flatRects(l.courseRows) + ",\"courseRestart\":" + flatRects(l.courseRestart);
    out += ",\"courseProgress\":" + quoted(l.courseProgress) + ",\"nextLesson\":" + rect(l.nextLesson);
    out += ",\"view\":" + quoted(l.view);
    out += ",\"mode\":" + quoted(l.mode) + ",\"lessonNote\":" + quoted(l.lessonNote) +
           ",\"courseNotes\":" + strings(l.courseNotes);
    out += ",\"status\":" + quoted(l.status) + ",\"browserLimits\":" + strings(l.browserLimits);
    out += ",\"layout\":" + quoted(l.layout) + ",\"pipelineWindow\":" + rect(l.pipelineWindow) +
           ",\"layoutCombo\":" + rect(l.layoutCombo) + ",\"layoutItems\":[";
    for (std::size_t i = 0; i < l.layoutItems.size(); ++i)
        out += (i ? "," : "") + number(l.layoutItems[i].x) + "," + number(l.layoutItems[i].y);
    out += "],\"msaaCombo\":" + rect(l.msaaCombo) + ",\"msaaItems\":[";
    for (std::size_t i = 0; i < l.msaaItems.size(); ++i)
        out += (i ? "," : "") + number(l.msaaItems[i].x) + "," + number(l.msaaItems[i].y);
    out += "],\"msaaGreyed\":[";
    for (std::size_t i = 0; i < l.msaaGreyed.size(); ++i) out += (i ? "," : "") + std::to_string(l.msaaGreyed[i]);
    out += "],\"msaaSamples\":" + std::to_string(l.msaaSamples) + ",\"msaaComplexBox\":" + rect(l.msaaComplexBox) +
           ",\"positionSampleCombo\":" + rect(l.positionSampleCombo) +
           ",\"positionSample\":" + std::to_string(l.positionSample);
    out += ",\"toolsImage\":[" + std::to_string(l.toolsImage.x) + "," + std::to_string(l.toolsImage.y) + "]";
    out += ",\"toolsRegion\":[" + std::to_string(l.toolsRegion.x) + "," + std::to_string(l.toolsRegion.y) + "," +
           std::to_string(l.toolsRegion.z) + "," + std::to_string(l.toolsRegion.w) + "]";
    out += ",\"frameWindow\":" + rect(l.frameWindow) + ",\"frameButton\":" + rect(l.frameButton) +
           ",\"stopButton\":" + rect(l.stopButton);
    out += ",\"stopAfter\":" + quoted(l.stopAfter) + ",\"stoppedAfter\":" + quoted(l.stoppedAfter);
    out += ",\"frameTargets\":" + strings(l.frameTargets);
    out += ",\"cameraInside\":[";
    for (std::size_t i = 0; i < l.cameraInside.size(); ++i) out += (i ? "," : "") + std::to_string(l.cameraInside[i]);
    out += "],\"wireframes\":" + std::to_string(l.wireframes);
    out += ",\"wireframesToggle\":" + rect(l.wireframesToggle) + ",\"wireframesAll\":" + rect(l.wireframesAll);
    out += std::string(",\"litDiffShown\":") + (l.litDiffShown ? "true" : "false");
    out += std::string(",\"everyLight\":") + (l.everyLight ? "true" : "false");
    out += ",\"checksButton\":" + rect(l.checksButton) + ",\"findings\":" + std::to_string(l.findings) +
           ",\"firstFinding\":" + rect(l.firstFinding) + ",\"markedFinding\":" + std::to_string(l.markedFinding) +
           ",\"precisionLines\":" + std::to_string(l.precisionLines);
    out += std::string(",\"overview\":") + (l.overview ? "true" : "false");
    out += ",\"overviewButton\":" + rect(l.overviewButton) + ",\"overviewCells\":" + strings(l.overviewCells);
    out += ",\"uiScale\":" + number(l.uiScale);
    out += ",\"dockLayout\":" + quoted(l.dockLayout);
    out += ",\"viewerArea\":[" + number(l.viewerArea.x) + "," + number(l.viewerArea.y) + "]";
    out += ",\"docks\":" + strings(l.docks);
    out += ",\"windowTabs\":" + flatRects(l.windowTabs);
    out += ",\"lightsWindow\":" + rect(l.lightsWindow) + ",\"plotRect\":" + rect(l.plotRect) +
           ",\"kqField\":" + rect(l.kqField);
    out += ",\"plotRadius\":" + number(l.plotRadius) + ",\"plotGhostRadius\":" + number(l.plotGhostRadius);
    out += ",\"plotPopup\":" + rect(l.plotPopup) + ",\"plotPopupRadius\":" + number(l.plotPopupRadius);
    out += ",\"plotLight\":[";
    for (std::size_t i = 0; i < l.plotLight.size(); ++i) {
        char text[32];
        std::snprintf(text, sizeof text, "%.9g", double(l.plotLight[i]));  // every digit of a float
        out += (i ? "," : "") + std::string(text);
    }
    out += "]";
    out += ",\"gbuffer\":" + quoted(l.gbuffer);
    out += ",\"frameSize\":[" + std::to_string(l.frameSize.x) + "," + std::to_string(l.frameSize.y) + "]";
    out += ",\"fileMenu\":" + rect(l.fileMenu) + ",\"viewMenu\":" + rect(l.viewMenu) +
           ",\"resetLayoutItem\":" + rect(l.resetLayoutItem) + ",\"uiScaleMenu\":" + rect(l.uiScaleMenu) +
           ",\"uiScaleItems\":" + flatRects(l.uiScaleItems) + ",\"openGBufferItem\":" + rect(l.openGBufferItem) +
           ",\"openSceneItem\":" + rect(l.openSceneItem) + ",\"openFolderItem\":" + rect(l.openFolderItem) +
           ",\"exportAllItem\":" + rect(l.exportAllItem) + ",\"windowShotItem\":" + rect(l.windowShotItem) +
           ",\"gbufferBrowser\":" + (l.gbufferBrowser ? "true" : "false");
    out += ",\"captureItem\":" + rect(l.captureItem) + ",\"captureDialog\":" + (l.captureDialog ? "true" : "false") +
           ",\"captureCommand\":" + rect(l.captureCommand) + ",\"captureFrame\":" + rect(l.captureFrame) +
           ",\"captureOut\":" + rect(l.captureOut) + ",\"captureEgl\":" + rect(l.captureEgl) +
           ",\"captureButton\":" + rect(l.captureButton) + ",\"capturing\":" + (l.capturing ? "true" : "false");
    out += ",\"captureError\":" + quoted(l.captureError);
    // Pairs, not an object: a pass's name as a key would read as a field of the line itself to
    // the shell tests' field lookups ("wireframes" is both).
    out += ",\"timing\":" + quoted(l.timing) + ",\"passMs\":[";
    for (std::size_t i = 0; i < l.passMs.size(); ++i)
        out += std::string(i ? "," : "") + "[" + quoted(l.passMs[i].first) + "," + number(l.passMs[i].second) + "]";
    return out + "]}";
}

std::optional<std::string> FrameLog::open(std::string const& path) {
    file_.reset(std::fopen(path.c_str(), "w"));
    if (!file_) return "Cannot write the frame log " + path + ": " + std::strerror(errno) + ".";
    // One line, one write(): a buffer larger than any line, flushed after each, so a test reading
    // the log while the editor runs seldom sees half a line (tests/support/ui_common.sh's `last`
    // skips one all the same).
    std::setvbuf(file_.get(), nullptr, _IOFBF, std::size_t{1} << 16);
    return std::nullopt;
}

void FrameLog::write(FrameLogLine const& line) {
    if (!file_) return;
    std::string const text = frameLogJson(line) + "\n";
    std::fwrite(text.data(), 1, text.size(), file_.get());
    std::fflush(file_.get());
}

}  // namespace gbl::ui
