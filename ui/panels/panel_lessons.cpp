// Lessons window.
#include "panels/panel_lessons.h"
#include "panels/item_rect.h"

#include "model/browser_files.h"
#include "model/lesson_claims.h"
#include "panels/layout.h"
#include "panels/panel_file_browser.h"
#include "panels/panel_glossary.h"
#include "panels/string_input.h"
#include "panels/wrapped_text.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <utility>
#include <vector>

namespace gbl::ui {

namespace {

bool inputText(char const* label, std::string& s, bool multiline) {
    ImGuiInputTextFlags const flags = ImGuiInputTextFlags_CallbackResize;
    if (multiline)
        return ImGui::InputTextMultiline(label, s.data(), s.capacity() + 1,
                                         ImVec2(-1.0f, ImGui::GetTextLineHeight() * 2.6f), flags, stringResizeCallback,
                                         &s);
    ImGui::SetNextItemWidth(-1.0f);
    return ImGui::InputText(label, s.data(), s.capacity() + 1, flags, stringResizeCallback, &s);
}

std::string formatNumber(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", double(v));
    return buf;
}

// The last item's centre in window coordinates; (0, 0) unless it is wholly in view (scrolled
// partly out, a click at its centre could land on the next window). In view: inside the clip
// rectangle items are drawn with, which in the step's region is also clipped by the window.
glm::vec2 itemCentre() {
    ImVec2 const a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    float const top = ImGui::GetWindowDrawList()->GetClipRectMin().y;
    float const bottom = ImGui::GetWindowDrawList()->GetClipRectMax().y;
    if (!ImGui::IsItemVisible() || a.y < top - 0.5f || b.y > bottom + 0.5f) return {0.0f, 0.0f};
    return {(a.x + b.x) * 0.5f, (a.y + b.y) * 0.5f};
}

// The last item's rectangle (x, y, width, height) in window coordinates; 0 unless wholly in view.
glm::vec4 itemRect() {
    return itemCentre() == glm::vec2(0.0f) ? glm::vec4(0.0f) : lastItemRect();
}

// What this context cannot run (LessonState::lessonNotes, stepNote), in the warning colour.
void drawLimitNote(std::string const& note) {
    if (note.empty()) return;
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.7f, 0.35f, 1.0f));
    wrappedText("%s", note.c_str());
    ImGui::PopStyleColor();
}

std::string countsLine(LessonCounts const& c) {
    std::string line = "steps " + std::to_string(c.stepsSeen) + "/" + std::to_string(c.steps);
    if (c.tasks > 0) line += ", tasks " + std::to_string(c.tasksDone) + "/" + std::to_string(c.tasks);
    if (c.predictionsAsked > 0)
        line +=
            ", predictions " + std::to_string(c.predictionsRight) + "/" + std::to_string(c.predictionsAsked) + " right";
    return line;
}

// The course: every lesson in order with the student's progress. A row opens its lesson where the
// student left it; Restart forgets that lesson's progress.
void drawCourse(LessonState& state, std::span<Lesson const> lessons, std::span<LessonCounts const> counts) {
    if (lessons.empty()) {
        wrappedText("No lessons were found.");
        return;
    }
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    wrappedText("%zu lessons: click one to open it where you left it.", lessons.size());
    ImGui::PopStyleColor();
    float const restartWidth = ImGui::CalcTextSize("Restart").x + ImGui::GetStyle().FramePadding.x * 2.0f;
    state.courseRows.assign(lessons.size(), glm::vec4(0.0f));
    state.courseRestart.assign(lessons.size(), glm::vec4(0.0f));
    for (std::size_t i = 0; i < lessons.size(); ++i) {
        LessonCounts const c = i < counts.size() ? counts[i] : LessonCounts{};
        ImGui::PushID(int(i));
        std::string const label = std::to_string(i + 1) + ". " + lessons[i].title;
        float const rowWidth =
            std::max(1.0f, ImGui::GetContentRegionAvail().x - restartWidth - ImGui::GetStyle().ItemSpacing.x);
        bool const started = c.stepsSeen > 0;
        ImGui::PushStyleColor(ImGuiCol_Text,
                              started ? ImGui::GetStyleColorVec4(ImGuiCol_Text) : ImVec4(0.8f, 0.8f, 0.8f, 1.0f));
        if (ImGui::Selectable(label.c_str(), int(i) == state.picked, 0, ImVec2(rowWidth, 0.0f))) {
            state.picked = int(i);
            state.startRequest = int(i);
        }
        ImGui::PopStyleColor();
        state.courseRows[i] = itemRect();
        if (i == 0) state.buttonCentres[0] = itemCentre();
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", lessons[i].summary.c_str());
        ImGui::SameLine();
        ImGui::BeginDisabled(!started);
        if (ImGui::SmallButton("Restart")) state.restartRequest = int(i);
        ImGui::EndDisabled();
        state.courseRestart[i] = itemRect();
        ImGui::Indent();
        ImGui::PushStyleColor(ImGuiCol_Text, c.stepsSeen == c.steps && c.tasksDone == c.tasks && c.steps > 0
                                                 ? ImVec4(0.5f, 0.9f, 0.5f, 1.0f)
                                                 : ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        wrappedText("%s", countsLine(c).c_str());
        ImGui::PopStyleColor();
        if (i < state.lessonNotes.size()) drawLimitNote(state.lessonNotes[i]);
        ImGui::Unindent();
        ImGui::PopID();
    }
}

// The prediction the step asks for before it reveals: its prompt and choices, then whether it was
// right (the explanation follows in the step's text).
void drawPrediction(LessonState& state, LessonPrediction const& p, LessonValues const& values) {
    if (!state.predicted) {
        ImGui::TextColored(ImVec4(0.75f, 0.6f, 1.0f, 1.0f), "Predict first");
        wrappedText("%s", substituteLessonText(p.prompt, values).c_str());
        if (!p.choices.empty()) {
            for (std::size_t i = 0; i < p.choices.size(); ++i) {
                ImGui::PushID(int(i));
                // The choice's text wraps beside its button (a RadioButton's own label does not).
                if (ImGui::RadioButton("##choice", state.predictChoice == int(i))) state.predictChoice = int(i);
                if (i == 0) state.buttonCentres[6] = itemCentre();
                ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
                ImGui::BeginGroup();  // its second line starts under its first, not under the button
                wrappedText("%s", p.choices[i].c_str());
                ImGui::EndGroup();
                if (ImGui::IsItemClicked()) state.predictChoice = int(i);
                ImGui::PopID();
            }
            // The button beside the last choice where it fits: one line less in a short window.
            float const button = ImGui::CalcTextSize("Check my prediction").x + ImGui::GetStyle().FramePadding.x * 2.0f;
            if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + button <
                ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x)
                ImGui::SameLine();
        } else {
            ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
            ImGui::InputFloat("your number", &state.predictNumber, 0.0f, 0.0f, "%.3g");
            state.buttonCentres[6] = itemCentre();
        }
        ImGui::BeginDisabled(!p.choices.empty() && state.predictChoice < 0);
        if (ImGui::Button("Check my prediction")) {
            state.predictRequested = true;
            state.scrollToResult = true;
        }
        state.buttonCentres[5] = itemCentre();
        ImGui::EndDisabled();
        return;
    }
    std::string const right = p.choices.empty()
                                  ? formatNumber(p.number) + " (within " + formatNumber(p.tolerance) + ")"
                                  : p.choices[std::size_t(std::clamp(p.correct, 0, int(p.choices.size()) - 1))];
    if (state.predictedRight)
        ImGui::TextColored(ImVec4(0.5f, 0.9f, 0.5f, 1.0f), "Right: %s", right.c_str());
    else {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.6f, 0.45f, 1.0f));
        wrappedText("Not quite: the answer is %s", right.c_str());
        ImGui::PopStyleColor();
    }
}

// The step's tasks as a checklist, ticked live by the editor loop (model/lesson_tasks.h); a task
// left unmet for a while shows its hint, which names the tool to use.
void drawTasks(LessonState const& state, LessonStep const& step, LessonValues const& values) {
    if (step.tasks.empty()) return;
    std::size_t done = 0;
    for (std::size_t i = 0; i < step.tasks.size(); ++i) done += i < state.tasks.size() && state.tasks[i].met;
    ImGui::TextColored(ImVec4(0.55f, 0.9f, 0.8f, 1.0f), "Tasks (%zu of %zu done)", done, step.tasks.size());
    for (std::size_t i = 0; i < step.tasks.size(); ++i) {
        TaskProgress const progress = i < state.tasks.size() ? state.tasks[i] : TaskProgress{};
        std::string const goal = substituteLessonText(step.tasks[i].goal, values);
        if (progress.met) {
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.5f, 0.9f, 0.5f, 1.0f));
            wrappedText("[x] %s", goal.c_str());
            ImGui::PopStyleColor();
            continue;
        }
        wrappedText("[ ] %s", goal.c_str());
    }
}

// The hints due (a task left unmet for kTaskHintSeconds), one paragraph each; drawn below the
// step's region, so a hint never pushes the step's text out of view.
std::vector<std::string> dueHints(LessonState const& state, LessonStep const& step, LessonValues const& values) {
    std::vector<std::string> hints;
    for (std::size_t i = 0; i < step.tasks.size() && i < state.tasks.size(); ++i)
        if (state.tasks[i].hint && !state.tasks[i].met)
            hints.push_back("Hint: " + substituteLessonText(step.tasks[i].hint, values));
    return hints;
}

// "Terms: NDC, window-space depth": the glossary's terms the step's text uses; hover for the
// definition, click to open the glossary there.
void drawTerms(LessonState& state, LessonStep const& step, Glossary const& glossary) {
    std::string all = step.text.look + "\n" + step.text.equation + "\n" + step.text.question;
    if (step.predict) all += "\n" + step.predict->prompt;
    std::vector<int> const terms = glossaryTermsIn(glossary, all);
    if (terms.empty()) return;
    ImGui::TextDisabled("Terms:");
    float const right = ImGui::GetWindowContentRegionMax().x + ImGui::GetWindowPos().x;
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(3.0f, 0.0f));
    for (int i : terms) {
        GlossaryTerm const& t = glossary.terms[std::size_t(i)];
        float const w = ImGui::CalcTextSize(t.term.c_str()).x + 6.0f;
        ImGui::SameLine();
        if (ImGui::GetCursorScreenPos().x + w > right) ImGui::NewLine();
        ImGui::PushID(i);
        if (ImGui::SmallButton(t.term.c_str())) {
            state.glossaryRequested = true;
            state.glossaryTerm = t.term;
        }
        if (i == terms.front()) state.buttonCentres[8] = itemCentre();
        glossaryTooltip(t);
        ImGui::PopID();
    }
    ImGui::PopStyleVar();
}

// The height the window keeps below the step's region: the hints, the message, the load errors and
// the authoring header, each as drawn after the step.
float footerHeight(LessonState const& state, std::span<std::string const> loadErrors,
                   std::span<std::string const> hints) {
    ImGuiStyle const& style = ImGui::GetStyle();
    float const width = ImGui::GetContentRegionAvail().x;
    float h = style.ItemSpacing.y * 3.0f + ImGui::GetFrameHeight();
    auto text = [&](std::string const& t) {
        h += ImGui::CalcTextSize(t.c_str(), nullptr, false, width).y + style.ItemSpacing.y;
    };
    for (auto const& t : hints) text(t);
    if (!state.message.empty()) text(state.message);
    for (auto const& e : loadErrors) text(e);
    return h;
}

// A step: its controls and title stay at the top; below them the step's region (checklist,
// prediction, answer button, text, question, answer) scrolls on its own and keeps at least
// kLessonRegionLines lines (the layout grows the window to give them); the hints come after it.
void drawStep(LessonState& state, std::span<Lesson const> lessons, LessonValues const& values, Glossary const& glossary,
              std::span<std::string const> loadErrors) {
    Lesson const& lesson = lessons[std::size_t(state.lesson)];
    int const n = int(lesson.steps.size());
    LessonStep const& step = lesson.steps[std::size_t(std::clamp(state.step, 0, n - 1))];
    ImGui::BeginDisabled(state.step <= 0);
    if (ImGui::Button("< Back")) state.stepRequest = state.step - 1;
    state.buttonCentres[1] = itemCentre();
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(state.step >= n - 1);
    if (ImGui::Button("Next >")) state.stepRequest = state.step + 1;
    state.buttonCentres[2] = itemCentre();
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Leave")) state.leaveRequested = true;
    state.buttonCentres[3] = itemCentre();
    ImGui::SameLine();
    if (ImGui::Button("Glossary")) state.glossaryRequested = true;
    state.buttonCentres[7] = itemCentre();
    ImGui::SameLine();
    ImGui::TextDisabled("%d / %d", state.step + 1, n);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s, step %d of %d", lesson.title.c_str(), state.step + 1, n);
    // The step's title only: the lesson's is in the course the student opened it from, and a
    // second line here would push the checklist or the prediction's button below the fold.
    wrappedText("%s", step.text.title.c_str());
    drawLimitNote(state.stepNote);
    bool const waiting = step.predict && !state.predicted;  // the step's change is not shown yet
    // At the end of the last step (its prediction made), the course goes on.
    if (!waiting && state.step >= n - 1 && state.lesson + 1 < int(lessons.size())) {
        std::string const label = "Next lesson: " + lessons[std::size_t(state.lesson) + 1].title;
        if (ImGui::Button(label.c_str())) state.startRequest = state.lesson + 1;
        state.nextLessonButton = itemRect();
    }
    ImGui::Separator();
    std::vector<std::string> const hints = waiting ? std::vector<std::string>{} : dueHints(state, step, values);
    float const line = ImGui::GetTextLineHeightWithSpacing();
    float const room = ImGui::GetContentRegionAvail().y - footerHeight(state, loadErrors, hints);
    state.regionShortPx = std::max(0.0f, kLessonRegionLines * line - room);
    // A line a few pixels wider than the region (a row of buttons) scrolls sideways, not cut off.
    ImGui::BeginChild("step region", ImVec2(0.0f, std::max(room, kLessonRegionLines * line)), ImGuiChildFlags_None,
                      ImGuiWindowFlags_HorizontalScrollbar);
    if (!waiting) drawTasks(state, step, values);  // what to do with the tools, before the answer is revealed
    if (step.predict) drawPrediction(state, *step.predict, values);
    if (!waiting) {
        if (ImGui::Button(state.answerShown ? "Hide answer" : "Show answer")) {
            state.answerShown = !state.answerShown;
            state.scrollToResult = state.answerShown;
        }
        state.buttonCentres[4] = itemCentre();
    }
    drawTerms(state, step, glossary);
    ImGui::Spacing();
    if (!waiting) {
        wrappedText("%s", substituteLessonText(step.text.look, values).c_str());
        ImGui::Spacing();
        ImGui::TextColored(ImVec4(0.55f, 0.8f, 1.0f, 1.0f), "Equation");
        wrappedText("%s", substituteLessonText(step.text.equation, values).c_str());
    }
    if (step.predict && state.predicted) {
        ImGui::Spacing();
        if (!state.answerShown && std::exchange(state.scrollToResult, false))
            ImGui::SetScrollHereY(0.0f);  // the explanation in view
        ImGui::TextColored(ImVec4(0.75f, 0.6f, 1.0f, 1.0f), "Your prediction");
        wrappedText("%s", substituteLessonText(step.predict->prompt, values).c_str());
        wrappedText("%s", substituteLessonText(step.predict->explain, values).c_str());
    }
    if (waiting) {
        // The question and its answer would give the prediction away: they follow it.
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        wrappedText("The step's question and its answer follow your prediction.");
        ImGui::PopStyleColor();
    } else {
        ImGui::Spacing();
        ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.45f, 1.0f), "Question");
        wrappedText("%s", substituteLessonText(step.text.question, values).c_str());
        if (state.answerShown) {
            if (std::exchange(state.scrollToResult, false)) ImGui::SetScrollHereY(0.0f);  // the answer in view
            ImGui::TextColored(ImVec4(0.5f, 0.9f, 0.5f, 1.0f), "Answer");
            wrappedText("%s", substituteLessonText(step.text.answer, values).c_str());
        }
    }
    if (step.claim) ImGui::TextDisabled("checked claim: %s", std::string(claimKindInfo(step.claim->kind).name).c_str());
    ImGui::EndChild();
    // The region's lines in view: its height inside the window's clip rectangle, over a line.
    float const top = std::max(ImGui::GetItemRectMin().y, ImGui::GetWindowDrawList()->GetClipRectMin().y);
    float const bottom = std::min(ImGui::GetItemRectMax().y, ImGui::GetWindowDrawList()->GetClipRectMax().y);
    state.regionLines = std::max(0.0f, bottom - top) / line;
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    for (std::string const& h : hints) wrappedText("%s", h.c_str());
    state.hintsShown = int(hints.size());
    ImGui::PopStyleColor();
}

void drawAuthoring(LessonState& state, FileBrowserState& browser) {
    if (!ImGui::CollapsingHeader("Save this state as a step")) return;
    ImGui::TextUnformatted("Title");
    inputText("##title", state.draft.title, false);
    ImGui::TextUnformatted("What to look at");
    inputText("##look", state.draft.look, true);
    ImGui::TextUnformatted("Equation ({light.kq}, {pixel.lit})");
    inputText("##equation", state.draft.equation, true);
    ImGui::TextUnformatted("Question");
    inputText("##question", state.draft.question, true);
    ImGui::TextUnformatted("Answer (revealed after trying)");
    inputText("##answer", state.draft.answer, true);
    // A task from a change: remember the start, make the change, save. The step shows the start.
    if (ImGui::Button("Remember this state as the task start")) state.taskStartRequested = true;
    ImGui::SameLine();
    ImGui::TextDisabled(state.taskStart ? "(remembered)" : "(none yet)");
    ImGui::BeginDisabled(!state.taskStart);
    ImGui::Checkbox("Add tasks: the step shows the start and asks for the change to this state", &state.saveWithTasks);
    ImGui::EndDisabled();
    ImGui::TextUnformatted("Lesson file (appended to)");
    inputText("##savepath", state.savePath, false);
    if (ImGui::Button("Save step")) state.saveStepRequested = true;
    ImGui::SameLine();
    if (ImGui::Button("Open lesson file...") && !pickFilesInBrowser())  // the browser's picker: a drop
        openFileBrowser(browser, FileBrowserPurpose::OpenLesson, state.savePath);
}

}  // namespace

void drawLessonsPanel(LessonState& state, std::span<Lesson const> lessons, std::span<LessonCounts const> counts,
                      std::span<std::string const> loadErrors, LessonValues const& values, FileBrowserState& browser,
                      Glossary const& glossary, glm::vec4 placement) {
    state.buttonCentres = {};
    state.courseRows.clear();
    state.courseRestart.clear();
    state.nextLessonButton = glm::vec4(0.0f);
    state.regionLines = 0.0f;
    state.regionShortPx = 0.0f;
    state.hintsShown = 0;
    state.windowRect = glm::vec4(0.0f);
    bool const placed = placement.z > 0.0f && placement.w > 0.0f;
    if (placed) {
        ImGui::SetNextWindowPos(ImVec2(placement.x, placement.y));
        ImGui::SetNextWindowSize(ImVec2(placement.z, placement.w));
    }
    ImGuiWindowFlags const flags = placed ? ImGuiWindowFlags_NoDocking | ImGuiWindowFlags_NoMove |
                                                ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                                ImGuiWindowFlags_NoSavedSettings
                                          : ImGuiWindowFlags_None;
    if (ImGui::Begin(placed ? "Lesson##presentation" : windowName(EditorWindow::Lessons), nullptr, flags)) {
        state.windowRect = {ImGui::GetWindowPos().x, ImGui::GetWindowPos().y, ImGui::GetWindowWidth(),
                            ImGui::GetWindowHeight()};
        if (state.lesson >= 0 && state.lesson < int(lessons.size()))
            drawStep(state, lessons, values, glossary, loadErrors);
        else
            drawCourse(state, lessons, counts);
        if (!state.message.empty()) {
            ImVec4 const colour =
                state.messageIsError ? ImVec4(1.0f, 0.45f, 0.4f, 1.0f) : ImVec4(0.6f, 0.9f, 0.6f, 1.0f);
            ImGui::PushStyleColor(ImGuiCol_Text, colour);
            wrappedText("%s", state.message.c_str());
            ImGui::PopStyleColor();
        }
        for (auto const& e : loadErrors) wrappedText("%s", e.c_str());
        ImGui::Separator();
        drawAuthoring(state, browser);
    }
    ImGui::End();
    if (browser.purpose == FileBrowserPurpose::OpenLesson)
        if (auto path = drawFileBrowser(browser)) {
            state.openPath = *path;
            state.openRequested = true;
        }
}

}  // namespace gbl::ui
