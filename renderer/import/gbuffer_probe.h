// Before any attachment is decoded: every named file exists, is a regular file, has the frame's size
// (from its header, or its byte count for raw data) and the whole G-buffer fits the memory budget.
#pragma once

#include "import/gbuffer_manifest.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gbl {

// The most a G-buffer may take decoded (floats, the files and the attachments read from them). A
// 1920x1080 render --out folder takes about 0.3 GiB; 8000x8000 about 11 GiB.
inline constexpr std::uint64_t kGBufferMemoryBudget = std::uint64_t(4) << 30;

// One sentence naming the first file that cannot be used, or the budget; nullopt when all can be read.
std::optional<std::string> probeGBufferFiles(std::vector<ImageRef const*> const& refs,
                                             std::uint64_t budget = kGBufferMemoryBudget);

}  // namespace gbl
