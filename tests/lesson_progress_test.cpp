// Course progress (issue 27): the counts over a lesson's shape, marking and restarting, and the
// progress file: a round trip, a broken file read as no progress with one message naming the file,
// a lesson the library lacks or a step past a lesson's end kept in the file but left out of the
// counts, and Restart clearing one lesson only.
#include "model/lesson_progress.h"
#include "session/lesson_progress_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace gbl::ui;

namespace {

// Three steps: no task, two tasks, one task and a prediction.
LessonShape shape() {
    return LessonShape{{0, 2, 1}, {false, false, true}};
}

std::string tempPath(std::string const& name) {
    auto const dir = std::filesystem::temp_directory_path() / "gbl_lesson_progress_test";
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

void writeText(std::string const& path, std::string const& text) {
    std::ofstream(path, std::ios::binary) << text;
}

CourseProgress someProgress() {
    CourseProgress p;
    markStepSeen(p, "a", 0);
    markStepSeen(p, "a", 1);
    markTaskDone(p, "a", 1, 1);
    markStepSeen(p, "a", 2);
    markPrediction(p, "a", 2, false);
    markStepSeen(p, "b", 0);
    return p;
}

}  // namespace

TEST(LessonProgress, CountsWhatWasSeenDoneAndPredicted) {
    CourseProgress const p = someProgress();
    EXPECT_EQ(countProgress(p, "a", shape()), (LessonCounts{3, 3, 1, 3, 0, 1}));
    EXPECT_EQ(countProgress(p, "b", shape()), (LessonCounts{1, 3, 0, 3, 0, 0}));
    EXPECT_EQ(countProgress(p, "never", shape()), (LessonCounts{0, 3, 0, 3, 0, 0}));
    EXPECT_EQ(resumeStep(p, "a", 3), 2);
    EXPECT_EQ(resumeStep(p, "never", 3), 0);
}

TEST(LessonProgress, MarkingReportsChangesOnce) {
    CourseProgress p;
    EXPECT_TRUE(markStepSeen(p, "a", 1));
    EXPECT_FALSE(markStepSeen(p, "a", 1));
    EXPECT_TRUE(markStepSeen(p, "a", 0));  // going back moves where the lesson reopens
    EXPECT_EQ(resumeStep(p, "a", 3), 0);
    EXPECT_TRUE(markTaskDone(p, "a", 1, 0));
    EXPECT_FALSE(markTaskDone(p, "a", 1, 0));
    // Only the first prediction counts: after it the answer is known.
    EXPECT_TRUE(markPrediction(p, "a", 2, false));
    EXPECT_FALSE(markPrediction(p, "a", 2, true));
    EXPECT_EQ(p.lessons["a"].steps[2].prediction, false);
}

TEST(LessonProgress, RestartClearsOneLessonOnly) {
    CourseProgress p = someProgress();
    CourseProgress const before = p;
    EXPECT_TRUE(restartLesson(p, "a"));
    EXPECT_EQ(countProgress(p, "a", shape()), (LessonCounts{0, 3, 0, 3, 0, 0}));
    EXPECT_EQ(p.lessons.at("b"), before.lessons.at("b"));
    EXPECT_FALSE(restartLesson(p, "a"));
    EXPECT_EQ(resumeStep(p, "a", 3), 0);
}

TEST(LessonProgressFile, RoundTrip) {
    CourseProgress const p = someProgress();
    std::string const path = tempPath("round_trip.json");
    ASSERT_EQ(saveProgress(path, p), std::nullopt);
    ProgressLoad const load = loadProgress(path);
    EXPECT_EQ(load.error, "");
    EXPECT_FALSE(load.missing);
    EXPECT_EQ(load.progress, p);
    // The file is 1-based, as --lesson ID:STEP is.
    EXPECT_NE(progressToJson(p).find("\"tasks_done\": [\n            2\n"), std::string::npos) << progressToJson(p);
}

TEST(LessonProgressFile, MissingFileIsNoProgressAndNoError) {
    ProgressLoad const load = loadProgress(tempPath("does_not_exist.json"));
    EXPECT_TRUE(load.missing);
    EXPECT_EQ(load.error, "");
    EXPECT_TRUE(load.progress.lessons.empty());
}

TEST(LessonProgressFile, BrokenFilesGiveNoProgressAndOneSentence) {
    struct Case {
        char const* text;
        char const* says;
    };
    Case const cases[] = {
        {"{\"format\": \"gbuffer-lab-lesson-progress\", \"version\": 1, \"lessons\": {", "parse error"},
        {"", "parse error"},
        {"[]", "format must be"},
        {R"({"format": "gbuffer-lab-lesson-progress", "version": 2, "lessons": {}})", "version must be 1"},
        {R"({"format": "gbuffer-lab-lesson-progress", "version": 1})", "lessons must be an object"},
        {R"({"format": "gbuffer-lab-lesson-progress", "version": 1, "lessons": {"a": {"at": 0, "steps": []}}})",
         "lessons.a.at must be a whole number from 1"},
        {R"({"format": "gbuffer-lab-lesson-progress", "version": 1,
             "lessons": {"a": {"at": 1, "steps": [{"step": 1, "tasks_done": ["x"]}]}}})",
         "lessons.a.steps[0].tasks_done[0] must be a whole number from 1"},
        {R"({"format": "gbuffer-lab-lesson-progress", "version": 1,
             "lessons": {"a": {"at": 1, "steps": [{"step": 1, "prediction": "maybe"}]}}})",
         "lessons.a.steps[0].prediction must be"},
        {R"({"format": "gbuffer-lab-lesson-progress", "version": 1, "lessons": {"a": {"at": 1, "steps": [], "x": 1}}})",
         "lessons.a.x is not a known field"},
    };
    for (Case const& c : cases) {
        std::string const path = tempPath("broken.json");
        writeText(path, c.text);
        ProgressLoad const load = loadProgress(path);
        EXPECT_TRUE(load.progress.lessons.empty()) << c.text;
        EXPECT_FALSE(load.missing);
        EXPECT_EQ(load.error.rfind(path + ": ", 0), 0u) << load.error;
        EXPECT_NE(load.error.find(c.says), std::string::npos) << load.error;
        EXPECT_EQ(load.error.find('\n'), std::string::npos) << load.error;
    }
}

TEST(LessonProgressFile, BrokenFileIsMovedAsideBeforeItIsWrittenOver) {
    std::string const path = tempPath("aside.json");
    writeText(path, "not json");
    ASSERT_NE(loadProgress(path).error, "");
    EXPECT_EQ(keepBrokenProgress(path), std::nullopt);
    ASSERT_EQ(saveProgress(path, someProgress()), std::nullopt);
    std::ifstream broken(path + ".broken");
    std::string text((std::istreambuf_iterator<char>(broken)), {});
    EXPECT_EQ(text, "not json");
    EXPECT_EQ(loadProgress(path).progress, someProgress());
}

TEST(LessonProgressFile, UnknownLessonsAndStepsPastTheEndAreKeptNotCounted) {
    std::string const path = tempPath("unknown.json");
    writeText(path, R"({"format": "gbuffer-lab-lesson-progress", "version": 1, "lessons": {
        "gone": {"at": 4, "steps": [{"step": 4, "tasks_done": [1]}]},
        "a": {"at": 9, "steps": [{"step": 2, "tasks_done": [2, 5]}, {"step": 9, "prediction": "right"}]}}})");
    ProgressLoad const load = loadProgress(path);
    ASSERT_EQ(load.error, "");
    // "a" has 3 steps: step 9 and step 2's task 5 are not counted, and it reopens at its last step.
    EXPECT_EQ(countProgress(load.progress, "a", shape()), (LessonCounts{1, 3, 1, 3, 0, 0}));
    EXPECT_EQ(resumeStep(load.progress, "a", 3), 2);
    // Written back, nothing is lost.
    EXPECT_EQ(parseProgress(progressToJson(load.progress), "x").progress, load.progress);
    EXPECT_TRUE(load.progress.lessons.contains("gone"));
}
