// KHR_draco_mesh_compression: Draco's decoder turned into the loader's attribute arrays, every count checked.
#include "gltf/draco.h"

#include "gltf/failure.h"

#if GBL_HAVE_DRACO
#include <draco/compression/decode.h>
#endif

namespace gbl {

bool gltfDecodesDraco() {
    return GBL_HAVE_DRACO != 0;
}

namespace gltf {

#if GBL_HAVE_DRACO

DracoPrimitive decodeDracoPrimitive(std::span<std::uint8_t const> bytes, std::map<std::string, int> const& attributeIds,
                                    std::map<std::string, int> const& components, std::string const& who,
                                    GltfLoadOptions const& options) {
    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<char const*>(bytes.data()), bytes.size());
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    if (!decoded.ok() || !decoded.value())
        fail(who + "'s Draco data cannot be decoded (" +
             printable(decoded.ok() ? std::string("not a mesh") : decoded.status().error_msg_string(), 100) + ")");
    draco::Mesh const& mesh = *decoded.value();

    DracoPrimitive out;
    out.vertexCount = mesh.num_points();
    if (out.vertexCount > options.maxVertices)
        fail(who + "'s Draco data has " + num(out.vertexCount) + " vertices, more than the limit of " +
             num(options.maxVertices));
    if (std::size_t(mesh.num_faces()) > options.maxTriangles)
        fail(who + "'s Draco data has " + num(mesh.num_faces()) + " triangles, more than the limit of " +
             num(options.maxTriangles));
    out.indices.reserve(std::size_t(mesh.num_faces()) * 3);
    for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f)
        for (int c = 0; c < 3; ++c) {
            std::uint32_t const index = mesh.face(f)[c].value();
            if (index >= out.vertexCount)
                fail(who + "'s Draco data has index " + std::to_string(index) + " but only " + num(out.vertexCount) +
                     " vertices");
            out.indices.push_back(index);
        }

    for (auto const& [name, id] : attributeIds) {
        auto const want = components.find(name);
        if (want == components.end()) continue;  // an attribute the loader does not use
        draco::PointAttribute const* attribute = id >= 0 ? mesh.GetAttributeByUniqueId(std::uint32_t(id)) : nullptr;
        if (!attribute)
            fail(who + "'s Draco data has no attribute " + std::to_string(id) + " for " + printable(name, 40));
        int const comps = want->second;
        if (attribute->num_components() != comps)
            fail(who + "'s Draco attribute " + printable(name, 40) + " has " +
                 std::to_string(int(attribute->num_components())) + " components per element; expected " +
                 std::to_string(comps));
        std::vector<double>& values = out.attributes[name];
        values.resize(out.vertexCount * std::size_t(comps));
        float element[4] = {};
        for (std::size_t i = 0; i < out.vertexCount; ++i) {
            // Converts quantised or normalised integers to the float values the accessor stands for.
            if (!attribute->ConvertValue<float>(attribute->mapped_index(draco::PointIndex(std::uint32_t(i))),
                                                std::int8_t(comps), element))
                fail(who + "'s Draco attribute " + printable(name, 40) + " cannot be read as numbers");
            for (int c = 0; c < comps; ++c) values[i * std::size_t(comps) + std::size_t(c)] = double(element[c]);
        }
    }
    return out;
}

#else

DracoPrimitive decodeDracoPrimitive(std::span<std::uint8_t const>, std::map<std::string, int> const&,
                                    std::map<std::string, int> const&, std::string const& who, GltfLoadOptions const&) {
    fail(who + " is Draco-compressed, but " + std::string(kNoDracoReason));
}

#endif

}  // namespace gltf
}  // namespace gbl
