// The numbers a shipped step's text states about its frame: each is either a placeholder filled
// from the student's own frame, or a measured value its claim bounds (so the claim, which
// lessons_gl_test runs at the student's frame sizes too, checks the number there). No text quotes
// the frame size the claims were first measured at.
#include "model/lesson_state.h"
#include "session/lesson_file.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <regex>
#include <string>
#include <vector>

using namespace gbl::ui;

namespace {

// Every text of a step the student reads: the step's, its prediction's and its tasks'.
std::vector<std::string> stepTexts(LessonStep const& s) {
    std::vector<std::string> out{s.text.title, s.text.look, s.text.equation, s.text.question, s.text.answer};
    if (s.predict) {
        out.push_back(s.predict->prompt);
        out.push_back(s.predict->explain);
        for (std::string const& c : s.predict->choices) out.push_back(c);
    }
    for (LessonTask const& t : s.tasks) {
        out.push_back(t.goal);
        out.push_back(t.hint);
    }
    return out;
}

std::string name(Lesson const& l, std::size_t i) {
    return l.id + ":" + std::to_string(i + 1);
}

LessonLibrary const& shipped() {
    static LessonLibrary const lib = loadLessonDir(defaultLessonDir());
    return lib;
}

// A frame size written out ("480×270", "640x360"): the student's frame is another size, so text
// says {frame.width}×{frame.height} instead. Tile sizes (16×16) are two digits and pass.
TEST(LessonNumbers, NoStepQuotesAFrameSize) {
    ASSERT_TRUE(shipped().errors.empty()) << shipped().errors.front();
    std::regex const size(R"([0-9]{3,}\s*(×|x)\s*[0-9]{3,})");
    for (Lesson const& l : shipped().lessons)
        for (std::size_t i = 0; i < l.steps.size(); ++i)
            for (std::string const& t : stepTexts(l.steps[i])) {
                EXPECT_FALSE(std::regex_search(t, size)) << name(l, i) << ": " << t;
                EXPECT_EQ(t.find("at the lesson's"), std::string::npos) << name(l, i) << ": " << t;
            }
}

// "about N %" is a share of the frame: the step's claim bounds it ([min_fraction, max_fraction)),
// and "about 0.0NN" a position error, which its position_error_below claim bounds ([at_least,
// bound)). A stated number without a claim that checks it is an error.
TEST(LessonNumbers, EveryMeasuredNumberLiesInItsClaimsRange) {
    std::regex const share(R"(about ([0-9.]+) %)");
    std::regex const error(R"(about (0\.0[0-9]+))");
    int stated = 0;
    for (Lesson const& l : shipped().lessons)
        for (std::size_t i = 0; i < l.steps.size(); ++i) {
            LessonStep const& s = l.steps[i];
            for (std::string const& t : stepTexts(s)) {
                for (auto it = std::sregex_iterator(t.begin(), t.end(), share); it != std::sregex_iterator(); ++it) {
                    ++stated;
                    ASSERT_TRUE(s.claim) << name(l, i) << " states " << (*it)[0] << " with no claim";
                    bool const ranged = s.claim->kind == ClaimKind::DiffersFrom ||
                                        s.claim->kind == ClaimKind::FewerEvaluations ||
                                        s.claim->kind == ClaimKind::ExecutedExceedsLit;
                    EXPECT_TRUE(ranged && s.claim->maxFraction < 1.0f)
                        << name(l, i) << " states " << (*it)[0] << " but its claim bounds no share";
                    float const v = std::stof((*it)[1]) / 100.0f;
                    EXPECT_GE(v, s.claim->minFraction) << name(l, i) << ": " << (*it)[0];
                    EXPECT_LT(v, s.claim->maxFraction) << name(l, i) << ": " << (*it)[0];
                }
                for (auto it = std::sregex_iterator(t.begin(), t.end(), error); it != std::sregex_iterator(); ++it) {
                    ++stated;
                    // position_from_depth:4 recalls step 3's value; that step's claim bounds it.
                    LessonStep const* bounding = &s;
                    if (t.find((*it)[0].str() + " (step ") != std::string::npos && i > 0) bounding = &l.steps[i - 1];
                    ASSERT_TRUE(bounding->claim && bounding->claim->kind == ClaimKind::PositionError)
                        << name(l, i) << " states " << (*it)[0] << " with no position_error_below claim";
                    float const v = std::stof((*it)[1]);
                    // "about" rounds to the digits written: 0.02 stands for 0.015 .. 0.025.
                    std::string const digits = (*it)[1];
                    float const half = 0.5f * std::pow(10.0f, -float(digits.size() - digits.find('.') - 1));
                    EXPECT_GE(v + half, bounding->claim->atLeast) << name(l, i) << ": " << (*it)[0];
                    EXPECT_LE(v - half, bounding->claim->bound) << name(l, i) << ": " << (*it)[0];
                    EXPECT_GT(bounding->claim->atLeast, 0.0f) << name(l, i) << ": a stated error needs at_least";
                }
            }
        }
    EXPECT_GE(stated, 6);  // position_from_depth 2-4, light_volumes:4, depth_blit:3
}

// The frame-wide shares of wasted work (fullscreen_pass:2, executed_vs_lit:1) are said in words
// (the pixel's own counts open the step's text, in view without scrolling)
// and bounded by their executed_exceeds_lit claim's range, which the GL test runs on the student's frame.
TEST(LessonNumbers, TheWastedWorkStepsBoundTheirShare) {
    for (char const* id : {"fullscreen_pass", "executed_vs_lit"}) {
        Lesson const* lesson = nullptr;
        for (Lesson const& l : shipped().lessons)
            if (l.id == id) lesson = &l;
        ASSERT_TRUE(lesson) << id;
        bool found = false;
        for (LessonStep const& s : lesson->steps)
            if (s.claim && s.claim->kind == ClaimKind::ExecutedExceedsLit && s.claim->maxFraction < 1.0f) {
                found = true;
                EXPECT_GE(s.claim->minFraction, 0.5f) << id << ": \"most of the work\" needs at least half";
                EXPECT_EQ(s.text.look.rfind("At the inspector's pixel {pixel.reached} of", 0), 0u)
                    << id << ": the pixel's counts open the text, not only below the inspector's fold";
            }
        EXPECT_TRUE(found) << id;
    }
}

// executed_exceeds_lit's share is optional; a range that is empty or out of 0..1 is one sentence
// naming the field, and the file is refused.
TEST(LessonNumbers, ABadWastedShareIsNamed) {
    nlohmann::json j = nlohmann::json::parse(R"({
      "format": "gbuffer-lab-lesson", "version": 2, "id": "demo", "title": "Demo",
      "steps": [{"title": "One", "look": "l", "equation": "e", "question": "q", "answer": "a",
                 "pixel": [0.5, 0.8], "pipeline": {"mode": "quad", "view": "heatmap"},
                 "claim": {"kind": "executed_exceeds_lit", "min_fraction": 0.85, "max_fraction": 0.93}}]
    })");
    LessonLoad const good = parseLesson(j.dump(), "demo.json");
    ASSERT_TRUE(good.lesson) << good.error;
    EXPECT_FLOAT_EQ(good.lesson->steps[0].claim->minFraction, 0.85f);
    EXPECT_FLOAT_EQ(good.lesson->steps[0].claim->maxFraction, 0.93f);
    j["steps"][0]["claim"]["max_fraction"] = 0.5;
    LessonLoad const empty = parseLesson(j.dump(), "demo.json");
    EXPECT_FALSE(empty.lesson);
    EXPECT_EQ(empty.error.rfind("demo.json: steps[0].claim.max_fraction must be greater than min_fraction", 0), 0u)
        << empty.error;
    j["steps"][0]["claim"]["max_fraction"] = 0.93;
    j["steps"][0]["claim"]["min_fraction"] = 1.5;
    LessonLoad const big = parseLesson(j.dump(), "demo.json");
    EXPECT_FALSE(big.lesson);
    EXPECT_EQ(big.error.rfind("demo.json: steps[0].claim.min_fraction", 0), 0u) << big.error;
}

}  // namespace
