// Reading a frame's declared passes (core/frame_passes.h) in the CPU tests of the pass lists
// (frame_passes_test, frame_pass_targets_test): the loops as one line, the passes' names, one pass.
#pragma once

#include "core/frame_passes.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace gbl::test {

// "PASS samples RESOURCE; " for each loop: empty when there is none.
inline std::string describe(std::vector<FeedbackLoop> const& loops) {
    std::string out;
    for (FeedbackLoop const& l : loops)
        out += std::string(passName(l.pass)) + " samples " + std::string(resourceName(l.resource)) + "; ";
    return out;
}

inline std::vector<std::string> names(std::vector<PassDecl> const& passes) {
    std::vector<std::string> out;
    for (PassDecl const& p : passes) out.emplace_back(p.name());
    return out;
}

// The pass `id` of `passes`; throws (failing the test) when the frame has none.
inline PassDecl const& find(std::vector<PassDecl> const& passes, PassId id) {
    for (PassDecl const& p : passes)
        if (p.id == id) return p;
    throw std::runtime_error("no pass " + std::string(passName(id)));
}

}  // namespace gbl::test
