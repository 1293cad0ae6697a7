// The Lessons window in the editor: the lesson files, the course progress file, the text's live
// values, and carrying out what the window asked for (start, step, leave, restart, save a step,
// open a file) with one undo entry per step.
#include "editor_loop.h"

#include "model/browser_files.h"
#include "model/lesson_claims.h"
#include "model/lesson_text.h"
#include "panels/panel_glossary.h"
#include "panels/panel_lessons.h"
#include "session/lesson_progress_file.h"

#include <chrono>
#include <filesystem>

namespace gbl {

namespace {

using ui::LessonState;

void report(Editor& editor, std::string message, bool error) {
    LessonState& l = editor.course.lessons;
    l.message = message;
    l.messageIsError = error;
    ui::logMessage(editor.state.log, "lessons: " + message, error);
}

glm::ivec2 frameSize(Editor const& editor) {
    return {editor.renderer->width(), editor.renderer->height()};
}

// What a lesson snapshot needs that this context cannot run: the reason of its lighting mode or
// its A/B side's (the renderer's words), or nullopt when it runs.
std::optional<std::string> snapshotUnavailable(Editor& editor, ui::LessonSnapshot const& shot) {
    if (auto why = editor.renderer->modeUnavailable(shot.pipeline.mode)) return why;
    if (shot.ab)
        if (auto why = editor.renderer->modeUnavailable(shot.ab->b.mode)) return why;
    return std::nullopt;
}

char const* contextName() {
    return ui::kInBrowser ? "this browser" : "this OpenGL context";
}

// The course's note per lesson: how many of its steps this context cannot run, and why.
void noteLessonLimits(Editor& editor) {
    LessonState& l = editor.course.lessons;
    auto const& lessons = editor.course.library.lessons;
    l.lessonNotes.assign(lessons.size(), std::string());
    for (std::size_t i = 0; i < lessons.size(); ++i) {
        int blocked = 0;
        std::optional<std::string> first;
        for (ui::LessonStep const& step : lessons[i].steps)
            if (auto why = snapshotUnavailable(editor, step.state)) {
                ++blocked;
                if (!first) first = why;
            }
        if (blocked == 0) continue;
        l.lessonNotes[i] = std::to_string(blocked) + " of " + std::to_string(lessons[i].steps.size()) +
                           " steps cannot run in " + contextName() + ": " + *first + ".";
    }
}

// Applies what a step shows, except a lighting mode this context cannot run: the viewport then
// keeps the mode it had (quad if that one cannot run either), A/B is off, and the step says so.
void applyShown(Editor& editor, ui::LessonSnapshot const& shown) {
    LightingMode const running = editor.state.pipeline.mode;
    ui::applyLessonSnapshot(shown, editor.state, frameSize(editor));
    LessonState& l = editor.course.lessons;
    l.stepNote.clear();
    std::optional<std::string> const why = snapshotUnavailable(editor, shown);
    if (!why) return;
    LightingMode const kept = editor.renderer->modeUnavailable(running) ? LightingMode::Quad : running;
    editor.state.pipeline.mode = kept;
    editor.state.ab.enabled = false;
    l.stepNote = std::string("This step cannot run in ") + contextName() + ": " + *why + ". The viewport stays in " +
                 std::string(enumName(kLightingModeNames, kept)) +
                 " mode; the text and the question still hold, and the desktop editor shows the step.";
}

// Reads the progress file once, with the lessons. A file that cannot be read gives one message and
// no progress; it stays as it is until there is new progress, and is then moved aside (.broken).
void loadProgress(Editor& editor) {
    std::string why;
    std::optional<std::string> const path = ui::progressFilePath(&why);
    if (!path) {
        ui::logMessage(editor.state.log, "lessons: progress is not kept: " + why, true);
        return;
    }
    editor.course.progressPath = *path;
    ui::ProgressLoad load = ui::loadProgress(*path);
    if (!load.error.empty()) {
        editor.course.progressBroken = true;
        ui::logMessage(editor.state.log,
                       "lessons: progress file not read, starting with no progress (" + load.error +
                           "); the file is kept as " + *path + ".broken when new progress is saved",
                       true);
        return;
    }
    editor.course.progress = std::move(load.progress);
}

// Writes the progress file; called whenever the progress changed.
void saveProgress(Editor& editor) {
    if (editor.course.progressPath.empty()) return;
    if (std::exchange(editor.course.progressBroken, false))
        if (auto error = ui::keepBrokenProgress(editor.course.progressPath))
            ui::logMessage(editor.state.log, "lessons: " + *error, true);
    if (auto error = ui::saveProgress(editor.course.progressPath, editor.course.progress))
        ui::logMessage(editor.state.log, "lessons: progress not saved: " + *error, true);
}

// Seconds on the editor's clock, for the tasks' hint timing.
double nowSeconds() {
    return std::chrono::duration<double>(EditorClock::now().time_since_epoch()).count();
}

// The step's checklist against the editor now: ticks what is met, and shows the hint of a task
// left unmet for kTaskHintSeconds. A step waiting for its prediction has not shown its change
// yet, so its tasks wait too.
void checkTasks(Editor& editor) {
    LessonState& l = editor.course.lessons;
    if (l.lesson < 0) return;
    ui::Lesson const& lesson = editor.course.library.lessons[std::size_t(l.lesson)];
    ui::LessonStep const& s = lesson.steps[std::size_t(l.step)];
    if (s.tasks.empty() || (s.predict && !l.predicted)) return;
    ui::TaskContext ctx;
    ctx.lights = editor.state.lights;
    ctx.stepLights = s.state.lights;
    ctx.pipeline = &editor.state.pipeline;
    ctx.pixelLocked = editor.state.inspector.locked;
    ctx.pixel = editor.state.inspector.pixel;
    ctx.frameSize = frameSize(editor);
    ctx.lessonSize = {lesson.width, lesson.height};
    ui::updateTasks(l.tasks, s.tasks, ctx, nowSeconds());
    bool changed = false;
    for (std::size_t i = 0; i < l.tasks.size(); ++i)
        if (l.tasks[i].met) changed |= ui::markTaskDone(editor.course.progress, lesson.id, l.step, int(i));
    if (changed) saveProgress(editor);
}

// Makes `scene` (as EditorState::sceneName) the editor's scene unless it is; the error sentence when it
// cannot be loaded (the editor keeps its scene).
std::optional<std::string> useScene(Editor& editor, std::string const& scene) {
    if (scene == editor.state.sceneName()) return std::nullopt;
    return editor.sceneLoader(scene, editor.defaultLightCount);
}

void showStep(Editor& editor, int step) {
    LessonState& l = editor.course.lessons;
    ui::Lesson const& lesson = editor.course.library.lessons[std::size_t(l.lesson)];
    l.step = std::clamp(step, 0, int(lesson.steps.size()) - 1);
    ui::LessonStep const& s = lesson.steps[std::size_t(l.step)];
    if (auto error = useScene(editor, ui::lessonStepScene(lesson, l.step)))
        report(editor, "step " + std::to_string(l.step + 1) + "'s scene could not be loaded: " + *error, true);
    l.predictChoice = -1;
    l.predictNumber = 0.0f;
    l.predicted = false;
    l.predictedRight = false;
    l.predictRequested = false;
    l.answerShown = false;
    l.tasks = ui::startTasks(s.tasks.size(), nowSeconds());
    // A step that asks for a prediction first shows the state before its change.
    bool const before = s.predict && s.predict->before;
    ui::LessonSnapshot shown = before ? *s.predict->before : s.state;
    if (before) shown.pixel = s.state.pixel;
    applyShown(editor, shown);
    editor.sessions->commitLessonStep(editor.state);
    editor.sessions->lessonStepShown(editor.state);
    editor.actionLog.push_back("lesson " + lesson.id + " step " + std::to_string(l.step + 1));
    l.message.clear();
    l.pixelFrameSize = frameSize(editor);
    if (ui::markStepSeen(editor.course.progress, lesson.id, l.step)) saveProgress(editor);
}

// The step's pixel is a fraction of the frame: when the viewport (and so the frame) changes
// size, the inspector follows it to the same surface point, as long as it is still locked.
void keepStepPixel(Editor& editor) {
    LessonState& l = editor.course.lessons;
    if (l.lesson < 0 || frameSize(editor) == l.pixelFrameSize || !editor.state.inspector.locked) return;
    auto const& pixel = editor.course.library.lessons[std::size_t(l.lesson)].steps[std::size_t(l.step)].state.pixel;
    if (pixel) editor.state.inspector.pixel = ui::lessonPixel(*pixel, frameSize(editor));
    l.pixelFrameSize = frameSize(editor);
}

// A step's lit pin (`lit_pin`) of another size than the frame compares nothing: it is taken again
// at the frame's size (the editor's first frames settle the viewport's size; a window resized).
void keepStepPin(Editor& editor) {
    LessonState const& l = editor.course.lessons;
    if (l.lesson < 0) return;
    ui::LitPin& pin = editor.state.litPin;
    glm::ivec2 const size = frameSize(editor);
    if (editor.course.library.lessons[std::size_t(l.lesson)].steps[std::size_t(l.step)].state.litPinDiff &&
        pin.showDiff && pin.pinned && pin.pinnedName.empty() && !pin.pinRequested &&
        (pin.pinned->width != size.x || pin.pinned->height != size.y))
        pin.pinRequested = true;
}

// Opens lesson `index` at `step`, or where the student left it. The lesson's scene (its glTF file
// or the default scene) replaces the editor's; Leave loads the editor's again.
void start(Editor& editor, int index, std::optional<int> step = std::nullopt) {
    LessonState& l = editor.course.lessons;
    if (index < 0 || index >= int(editor.course.library.lessons.size())) return;
    ui::Lesson const& next = editor.course.library.lessons[std::size_t(index)];
    int const at = std::clamp(step.value_or(ui::resumeStep(editor.course.progress, next.id, int(next.steps.size()))), 0,
                              int(next.steps.size()) - 1);
    std::string const scene = ui::lessonStepScene(next, at);
    if (l.lesson < 0) {
        closeImportedGBuffer(editor);  // the lesson returns to the scene, not to a G-buffer
        std::string const sceneBefore = editor.state.sceneName();
        ui::LessonReturn before = ui::captureLessonReturn(editor.state);
        editor.sessions->lessonStarting(editor.state);  // before the scene changes: were there edits?
        if (auto error = useScene(editor, scene)) {
            report(editor, "lesson " + next.id + " not opened: its scene could not be loaded: " + *error, true);
            return;
        }
        l.before = std::move(before);
        l.sceneBefore = sceneBefore;
    } else if (l.before) {
        // Another lesson: it starts from the editor as it was before any, not from the tools the
        // last one left open.
        if (auto error = useScene(editor, scene)) {
            report(editor, "lesson " + next.id + " not opened: its scene could not be loaded: " + *error, true);
            return;
        }
        ui::applyLessonReturn(*l.before, editor.state, frameSize(editor));
    }
    l.lesson = index;
    showStep(editor, at);
}

// "Restart" in the course view: that lesson's progress, and only that lesson's, is forgotten; the
// lesson then opens at its first step.
void restart(Editor& editor, int index) {
    if (index < 0 || index >= int(editor.course.library.lessons.size())) return;
    ui::Lesson const& lesson = editor.course.library.lessons[std::size_t(index)];
    if (!ui::restartLesson(editor.course.progress, lesson.id)) return;
    saveProgress(editor);
    editor.actionLog.push_back("lesson " + lesson.id + " restarted");
    report(editor, "progress of \"" + lesson.title + "\" cleared", false);
}

// The student's prediction: right or wrong, then the step's own state (its change) is applied.
void checkPrediction(Editor& editor) {
    LessonState& l = editor.course.lessons;
    if (l.lesson < 0) return;
    ui::Lesson const& lesson = editor.course.library.lessons[std::size_t(l.lesson)];
    ui::LessonStep const& s = lesson.steps[std::size_t(l.step)];
    if (!s.predict || l.predicted) return;
    l.predictedRight = ui::predictionRight(*s.predict, l.predictChoice, l.predictNumber);
    l.predicted = true;
    l.tasks = ui::startTasks(s.tasks.size(), nowSeconds());  // the tasks start with the step's change
    if (s.predict->before) {
        applyShown(editor, s.state);
        editor.sessions->commitLessonStep(editor.state);
        editor.sessions->lessonStepShown(editor.state);
    }
    editor.actionLog.push_back(std::string("lesson prediction ") + (l.predictedRight ? "right" : "wrong"));
    if (ui::markPrediction(editor.course.progress, lesson.id, l.step, l.predictedRight)) saveProgress(editor);
}

void leave(Editor& editor) {
    LessonState& l = editor.course.lessons;
    if (l.lesson < 0) return;
    // The scene first: loading one resets the lights and camera, which the return then puts back.
    std::optional<std::string> sceneError;
    if (!l.sceneBefore.empty()) sceneError = useScene(editor, l.sceneBefore);
    if (l.before) ui::applyLessonReturn(*l.before, editor.state, frameSize(editor));
    editor.sessions->commitLessonStep(editor.state);
    editor.sessions->lessonLeft();
    editor.actionLog.push_back("lesson left");
    l.before.reset();
    l.lesson = -1;
    l.step = 0;
    l.tasks.clear();
    l.stepNote.clear();
    if (sceneError) {
        report(editor,
               "left the lesson, but its scene stays: " + l.sceneBefore + " could not be loaded again: " + *sceneError,
               true);
    } else {
        report(editor, "left the lesson; the editor is as it was before", false);
    }
    l.sceneBefore.clear();
}

// The editor's state as a step shows it: no animation, the inspector's pixel as frame fractions.
ui::LessonSnapshot currentSnapshot(Editor const& editor) {
    ui::LessonSnapshot s = ui::captureLessonSnapshot(editor.state);
    s.animation = {};
    if (editor.state.inspector.pixel) {
        glm::ivec2 const size = frameSize(editor);
        s.pixel = (glm::vec2(*editor.state.inspector.pixel) + 0.5f) / glm::vec2(glm::max(size, glm::ivec2(1)));
    }
    return s;
}

void saveStep(Editor& editor) {
    LessonState& l = editor.course.lessons;
    ui::LessonStep step;
    step.text = l.draft;
    for (auto const* field :
         {&step.text.title, &step.text.look, &step.text.equation, &step.text.question, &step.text.answer})
        if (field->find_first_not_of(" \t\n") == std::string::npos) {
            report(editor, "type a title, what to look at, an equation, a question and its answer first", true);
            return;
        }
    step.state = currentSnapshot(editor);
    if (l.saveWithTasks) {
        // The step shows the remembered start; its tasks ask for the change made since.
        if (!l.taskStart) {
            report(editor, "remember the task start first, then make the change the task asks for", true);
            return;
        }
        step.tasks =
            ui::tasksFromChange(l.taskStart->pipeline, step.state.pipeline, l.taskStart->lights, step.state.lights);
        if (step.tasks.empty()) {
            report(editor, "no task to add: no pipeline setting and no light field changed since the remembered start",
                   true);
            return;
        }
        step.state = *l.taskStart;
    }
    step.defaultSceneLights = editor.defaultLightCount;
    std::string scene = editor.state.sceneName();
    step.defaultSceneGlass = scene == ui::kDefaultSceneGlass;
    if (scene == "default" || step.defaultSceneGlass) scene.clear();
    if (auto err = ui::appendLessonStep(l.savePath, step, scene)) {
        report(editor, *err, true);
        return;
    }
    // Read it back: what was written must be a lesson this editor opens.
    ui::LessonLoad const load = ui::loadLesson(l.savePath);
    if (!load.lesson) {
        report(editor, load.error, true);
        return;
    }
    report(editor,
           "saved step " + std::to_string(load.lesson->steps.size()) + " to " + l.savePath +
               (step.tasks.empty() ? "" : " with " + std::to_string(step.tasks.size()) + " task(s)"),
           false);
}

void open(Editor& editor, std::string const& path) {
    ui::LessonLoad load = ui::loadLesson(path);
    if (!load.lesson) {
        report(editor, load.error, true);
        return;
    }
    auto& lessons = editor.course.library.lessons;
    auto it =
        std::find_if(lessons.begin(), lessons.end(), [&](ui::Lesson const& l) { return l.id == load.lesson->id; });
    if (it != lessons.end() && editor.course.lessons.lesson == int(it - lessons.begin())) leave(editor);
    if (it == lessons.end())
        it = lessons.insert(lessons.end(), std::move(*load.lesson));
    else
        *it = std::move(*load.lesson);
    editor.course.lessons.picked = int(it - lessons.begin());
    noteLessonLimits(editor);
    report(editor, "opened " + path, false);
}

}  // namespace

void markLessonClaim(Editor& editor, bool rendered) {
    std::optional<ui::ViewportState::Mark>& mark = editor.state.viewport.lessonMark;
    LessonState const& l = editor.course.lessons;
    ui::LessonStep const* step = nullptr;
    if (l.lesson >= 0 && l.lesson < int(editor.course.library.lessons.size()))
        step = &editor.course.library.lessons[std::size_t(l.lesson)].steps[std::size_t(l.step)];
    // A step waiting for its prediction shows the state before its change: nothing of its own to mark.
    bool const wanted = step && step->claim && step->claim->mark && !(step->predict && !l.predicted);
    Renderer& renderer = *editor.renderer;
    if (!wanted || renderer.width() <= 0 || renderer.height() <= 0 || renderer.hasImportedGBuffer()) {
        mark.reset();
        return;
    }
    // Measured again on every new frame (the student may move the camera), from the attachments
    // the frame left; position_error_below reads only the position and the depth.
    if (!rendered && mark && editor.frameMemory.markedStep == std::pair(l.lesson, l.step)) return;
    editor.frameMemory.markedStep = {l.lesson, l.step};
    ui::ClaimImages images;
    images.position = renderer.readAttachment(Attachment::Position);
    images.depth = renderer.readAttachment(Attachment::Depth);
    glm::ivec2 const pixel = editor.state.inspector.pixel.value_or(glm::ivec2(0));
    ui::ClaimResult const result =
        ui::checkClaim(*step->claim, {editor.state.camera, editor.drawn, editor.state.pipeline, pixel}, images);
    std::optional<ui::ClaimMark> const m = ui::claimMark(*step->claim, result);
    if (m)
        mark = ui::ViewportState::Mark{m->pixel, m->value, m->label};
    else
        mark.reset();
}

void lessonLogFields(Editor const& editor, ui::FrameLogLine& line) {
    LessonState const& l = editor.course.lessons;
    if (auto const& m = editor.state.viewport.lessonMark)
        line.lessonMark = {float(m->pixel.x), float(m->pixel.y), m->value};
    if (l.lesson >= 0 && l.lesson < int(editor.course.library.lessons.size()))
        line.lesson = editor.course.library.lessons[std::size_t(l.lesson)].id + ":" + std::to_string(l.step + 1);
    line.lessonButtons.assign(l.buttonCentres.begin(), l.buttonCentres.end());
    line.lessonPrediction = l.predicted ? (l.predictedRight ? "right" : "wrong") : "";
    line.lessonAnswer = l.answerShown;
    line.lessonTasks.clear();
    for (ui::TaskProgress const& t : l.tasks) line.lessonTasks += t.met ? '1' : '0';
    line.lessonGlossary = editor.glossaryWindow.open;
    line.lessonGlossaryTerm = editor.glossaryWindow.shownTerm;
    line.view = std::string(enumName(kDebugViewNames, editor.state.pipeline.view));
    line.mode = std::string(enumName(kLightingModeNames, editor.state.pipeline.mode));
    line.lessonNote = l.lesson >= 0 ? l.stepNote : std::string();
    line.lessonLines = l.regionLines;
    line.lessonsWindow = l.windowRect;
    line.lessonHints = l.hintsShown;
    line.courseNotes = l.lessonNotes;
    line.courseRows = l.courseRows;
    line.courseRestart = l.courseRestart;
    line.nextLesson = l.nextLessonButton;
    line.courseProgress.clear();
    for (ui::Lesson const& lesson : editor.course.library.lessons) {
        ui::LessonCounts const c = ui::countProgress(editor.course.progress, lesson.id, ui::lessonShape(lesson));
        if (!line.courseProgress.empty()) line.courseProgress += '|';
        line.courseProgress += lesson.id + " " + std::to_string(c.stepsSeen) + "/" + std::to_string(c.steps) + " " +
                               std::to_string(c.tasksDone) + "/" + std::to_string(c.tasks) + " " +
                               std::to_string(c.predictionsRight) + "/" + std::to_string(c.predictionsAsked);
    }
}

void drawLessons(Editor& editor) {
    if (!editor.course.loaded) {
        editor.course.library = ui::loadLessonDir(ui::defaultLessonDir());
        editor.course.loaded = true;
        for (auto const& e : editor.course.library.errors) ui::logMessage(editor.state.log, e, true);
        loadProgress(editor);
        noteLessonLimits(editor);
        editor.course.glossary = ui::loadGlossary(ui::defaultGlossaryPath());
        if (!editor.course.glossary.error.empty()) ui::logMessage(editor.state.log, editor.course.glossary.error, true);
        if (editor.options.lesson) {
            ui::LessonRef const ref = ui::findLessonStep(editor.course.library, *editor.options.lesson);
            if (ref.lesson < 0) {
                report(editor, "--lesson: " + ref.error, true);
            } else {
                editor.course.lessons.picked = ref.lesson;
                start(editor, ref.lesson, ref.step);
            }
        }
    }
    checkTasks(editor);
    ui::EditorState const& state = editor.state;
    ui::LessonValues values;
    int const sel = state.lightsPanel.selected;
    if (sel >= 0 && sel < int(state.lights.size())) {
        values.light = state.lights[std::size_t(sel)];
        values.lightIndex = sel;
    }
    values.pixel = state.inspector.pixel;
    values.sample = state.inspector.sample;
    values.pipeline = state.pipeline;
    values.lightCount = int(state.lights.size());
    values.frameSize = frameSize(editor);
    std::vector<ui::LessonCounts> counts;
    for (ui::Lesson const& lesson : editor.course.library.lessons)
        counts.push_back(ui::countProgress(editor.course.progress, lesson.id, ui::lessonShape(lesson)));
    // The presentation layout shows a lesson beside the image, and no course without one.
    if (!state.layout.presentation || editor.course.lessons.lesson >= 0)
        ui::drawLessonsPanel(editor.course.lessons, editor.course.library.lessons, counts, editor.course.library.errors,
                             values, editor.course.browser, editor.course.glossary, state.layout.presentationLesson);

    LessonState& l = editor.course.lessons;
    if (l.restartRequest >= 0) restart(editor, std::exchange(l.restartRequest, -1));
    if (l.startRequest >= 0) start(editor, std::exchange(l.startRequest, -1));
    if (l.stepRequest >= 0) {
        int const to = std::exchange(l.stepRequest, -1);
        if (l.lesson >= 0) showStep(editor, to);
    }
    if (std::exchange(l.leaveRequested, false)) leave(editor);
    if (std::exchange(l.taskStartRequested, false)) {
        l.taskStart = currentSnapshot(editor);
        l.saveWithTasks = true;
        report(editor, "remembered the task start: change what the task should ask for, then save the step", false);
    }
    if (std::exchange(l.saveStepRequested, false)) saveStep(editor);
    if (std::exchange(l.openRequested, false)) open(editor, l.openPath);
    if (std::exchange(l.predictRequested, false)) checkPrediction(editor);
    if (std::exchange(l.glossaryRequested, false)) {
        editor.glossaryWindow.open = true;
        editor.glossaryWindow.focus = std::exchange(l.glossaryTerm, {});
    }
    ui::drawGlossaryWindow(editor.glossaryWindow, editor.course.glossary);
    keepStepPixel(editor);
    keepStepPin(editor);
}

}  // namespace gbl
