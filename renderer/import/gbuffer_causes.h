// Checks that name a cause the data proves rather than a symptom: a "normal" attachment that is really
// another target, normals whose encoding is the other one, positions that reproject to their own pixels
// only upside down, in the other space or through transposed matrices.
#pragma once

#include "import/gbuffer_checks.h"

#include <cstdint>
#include <vector>

namespace gbl {

// Adds those findings to `r` (and takes back the symptom findings a proven cause explains).
void addProvenCauses(ImportedGBuffer const& g, std::vector<std::uint8_t> const& geometry, GBufferCheckReport& r);

}  // namespace gbl
