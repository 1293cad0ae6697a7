// The glTF loader's accessor reader: buffer views and accessors with every byte range checked.
#pragma once

#include "gltf/loader.h"

#include <tiny_gltf.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace gbl::gltf {

// Reads a parsed model's accessors. Every failure throws LoadFailure naming `who`, the
// accessor or buffer view, and the range that does not fit.
class ModelReader {
public:
    // Checks every buffer view of the model against its buffer up front.
    ModelReader(tinygltf::Model const& model, GltfLoadOptions const& options);

    // The bytes of a buffer view, after checking it lies inside its buffer.
    std::span<std::uint8_t const> bufferView(int index, std::string const& who) const;

    // count * components values as double, normalised integers mapped to [0,1] / [-1,1].
    // wantComponents != 0 refuses an accessor with another number of components per element.
    std::vector<double> read(int index, std::string const& who, int wantComponents = 0) const;

private:
    void applySparse(tinygltf::Accessor const& acc, std::string const& name, int comps, std::size_t csize,
                     std::vector<double>& out) const;

    tinygltf::Model const& model_;
    GltfLoadOptions const& options_;
};

}  // namespace gbl::gltf
