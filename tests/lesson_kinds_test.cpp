// The task and claim kind tables (issue 24's one table per kind) on the CPU: every shipped task
// written back by taskToJson as its file holds it, docs/lessons.md documents exactly the kinds of
// each table with their fields, and each claim kind has one row. The tasks themselves:
// lesson_tasks_test.
#include "core/pipeline_fields.h"
#include "model/lesson_claims.h"
#include "model/lesson_tasks.h"
#include "session/lesson_file.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>

using namespace gbl;
using namespace gbl::ui;
using nlohmann::json;

namespace {

// Every shipped task, written by taskToJson, is the task its file holds (`lessons --json` prints
// these), and reads back to the same task.
TEST(LessonTasks, TaskToJsonWritesEachShippedTaskAsItsFileDoes) {
    LessonLibrary const lib = loadLessonDir(defaultLessonDir());
    ASSERT_TRUE(lib.errors.empty()) << lib.errors.front();
    int count = 0;
    for (Lesson const& l : lib.lessons)
        for (LessonStep const& s : l.steps) {
            if (s.tasks.empty()) continue;
            json file = json::parse(s.tasksJson);
            ASSERT_EQ(file.size(), s.tasks.size());
            for (std::size_t i = 0; i < s.tasks.size(); ++i, ++count) {
                // A setting's old name ("blit") is written under the field's name ("depth_copy").
                if (file[i].contains("setting"))
                    if (PipelineField const* f = findPipelineField(file[i]["setting"].get<std::string>()))
                        file[i]["setting"] = f->name;
                EXPECT_EQ(json::parse(taskToJson(s.tasks[i])), file[i]) << l.id << ": " << file[i].dump();
            }
        }
    EXPECT_GE(count, 5);
}

// The rows of docs/lessons.md's table under `heading`: kind name -> the rest of its row.
std::map<std::string, std::string> documentedKinds(std::string const& heading) {
    std::ifstream in(test::sourcePath("docs/lessons.md"));
    EXPECT_TRUE(in) << "cannot read docs/lessons.md";
    std::stringstream ss;
    ss << in.rdbuf();
    std::string const doc = ss.str();
    auto const start = doc.find(heading);
    EXPECT_NE(start, std::string::npos) << "docs/lessons.md has no \"" << heading << "\" section";
    if (start == std::string::npos) return {};
    auto const end = doc.find("\n#", start + 1);
    std::string const section = doc.substr(start, end == std::string::npos ? std::string::npos : end - start);
    std::regex const row(R"(\n\| `([a-z_]+)` \|([^\n]*))");
    std::map<std::string, std::string> rows;
    for (auto it = std::sregex_iterator(section.begin(), section.end(), row); it != std::sregex_iterator(); ++it)
        rows[(*it)[1]] = (*it)[2];
    return rows;
}

// Each documented row names every field of its kind, and the table lists exactly the kinds.
template <class Kinds, class Find>
void expectDocumented(std::string const& heading, Kinds const& kinds, Find find) {
    std::set<std::string> documented;
    for (auto const& [name, rest] : documentedKinds(heading)) {
        documented.insert(name);
        auto const* k = find(name);
        ASSERT_TRUE(k) << "docs/lessons.md documents a kind its table does not have: " << name;
        for (auto f : k->fields)
            EXPECT_NE(rest.find("`" + std::string(f) + "`"), std::string::npos) << name << " row lacks " << f;
        for (auto f : k->optionalFields)
            EXPECT_NE(rest.find("`" + std::string(f) + "`"), std::string::npos) << name << " row lacks " << f;
    }
    std::set<std::string> names;
    for (auto const& k : kinds) names.insert(std::string(k.name));
    EXPECT_EQ(documented, names) << heading;
}

// docs/lessons.md's task table lists exactly the kinds of taskKinds(), each with its fields.
TEST(LessonTasks, DocsDocumentExactlyTheTaskKinds) {
    expectDocumented("### Tasks", taskKinds(), findTaskKind);
}

// The same for the claim kinds (claimKinds(), issue 24's one table per kind).
TEST(LessonClaims, DocsDocumentExactlyTheClaimKinds) {
    expectDocumented("### Claims", claimKinds(), findClaimKind);
}

// The table's rows are the enum's values, once each, and each kind checks through its own row.
TEST(LessonClaims, EveryKindHasOneRow) {
    std::set<int> kinds;
    for (ClaimKindInfo const& k : claimKinds()) {
        EXPECT_TRUE(kinds.insert(int(k.kind)).second) << k.name;
        EXPECT_EQ(&claimKindInfo(k.kind), &k) << k.name;
        EXPECT_EQ(findClaimKind(k.name), &k) << k.name;
        EXPECT_TRUE(k.check) << k.name;
        EXPECT_FALSE(k.doc.empty()) << k.name;
    }
    EXPECT_EQ(kinds.size(), std::size_t(ClaimKind::ComplexShare) + 1);
}

}  // namespace
