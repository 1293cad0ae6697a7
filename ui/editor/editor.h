// Entry point of the interactive editor (the default command of gbuffer-lab).
#pragma once

#include <optional>
#include <string>

namespace gbl {

struct EditorOptions {
    std::optional<std::string> scenePath;       // glTF file; the default courtyard when empty
    std::optional<int> lightCount;              // default scene: number of lights (32 when unset)
    std::optional<std::string> screenshotPath;  // write the whole window as PNG after `frames`, then exit
    int frames = 0;                             // 0 = run until the window is closed
    int width = 1600;                           // window size in screen coordinates
    int height = 900;
    bool sizeGiven = false;                    // --size: taken as given; else the window fits the monitor's work area
    std::optional<std::string> sessionPath;    // session file to open (issue 6)
    std::optional<std::string> gbufferPath;    // another program's G-buffer to re-light (issue 28)
    std::optional<std::string> uiTestScript;   // run a UI test script (see ui/ui_script.h), exit 0 if it passes
    bool allowOutsideUris = false;             // glTF files may read files outside their folder
    bool glass = false;                        // default scene: its glass panes (DefaultSceneOptions::glass)
    std::string glLimit;                       // "3.3": pretend the context is at most that version
    bool vsync = true;                         // off for screenshots, tests and measurements
    std::optional<std::string> logFramesPath;  // one JSON line per frame (ui/model/frame_log.h)
    int frameSleepMs = 0;                      // a sleep per frame that still takes input: slow-machine tests
    bool continuousRender = false;             // render every frame, changed or not (timing)
    std::optional<std::string> lesson;         // "ID" or "ID:STEP": open this lesson step at start
    // A frame estimated above this many seconds (core/frame_cost.h) switches to the mode that gives
    // the same image sooner, with a message, instead of freezing the editor.
    double frameWarnSeconds = 2.0;
    // --ui-scale as given ("1.5"), checked by runEditor (model/ui_scale.h); it wins over the scale
    // kept with the window layout.
    std::optional<std::string> uiScale;
};

// Opens the window and runs until it is closed, the frame count is reached or the test script
// ends. Returns the process exit code: 0 success, 1 no display / GL failure / failed test,
// 2 bad input (unreadable scene, session or G-buffer, unwritable screenshot path, --ui-scale out of range).
int runEditor(EditorOptions const& options);

}  // namespace gbl
