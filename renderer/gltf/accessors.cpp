// The glTF loader's accessor reader: every index and byte range checked before it is read.
#include "gltf/accessors.h"

#include "gltf/failure.h"

#include <algorithm>
#include <climits>
#include <cstring>

namespace gbl::gltf {

namespace {

std::size_t componentSize(int type) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return 4;
        default:
            return 0;
    }
}

int componentCount(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return 1;
        case TINYGLTF_TYPE_VEC2:
            return 2;
        case TINYGLTF_TYPE_VEC3:
            return 3;
        case TINYGLTF_TYPE_VEC4:
            return 4;
        case TINYGLTF_TYPE_MAT2:
            return 4;
        case TINYGLTF_TYPE_MAT3:
            return 9;
        case TINYGLTF_TYPE_MAT4:
            return 16;
        default:
            return 0;
    }
}

double readComponent(std::uint8_t const* p, int type, bool normalized) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            std::int8_t v;
            std::memcpy(&v, p, 1);
            return normalized ? std::max(double(v) / 127.0, -1.0) : double(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return normalized ? double(*p) / 255.0 : double(*p);
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            std::int16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? std::max(double(v) / 32767.0, -1.0) : double(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? double(v) / 65535.0 : double(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            std::uint32_t v;
            std::memcpy(&v, p, 4);
            return double(v);
        }
        default: {
            float v;
            std::memcpy(&v, p, 4);
            return double(v);
        }
    }
}

}  // namespace

ModelReader::ModelReader(tinygltf::Model const& model, GltfLoadOptions const& options)
    : model_(model), options_(options) {
    for (std::size_t i = 0; i < model.bufferViews.size(); ++i) bufferView(int(i), "bufferView " + num(i));
}

std::span<std::uint8_t const> ModelReader::bufferView(int index, std::string const& who) const {
    if (index < 0 || std::size_t(index) >= model_.bufferViews.size())
        fail(who + " refers to buffer view " + std::to_string(index) + ", but the file has " +
             num(model_.bufferViews.size()));
    auto const& bv = model_.bufferViews[std::size_t(index)];
    if (bv.buffer < 0 || std::size_t(bv.buffer) >= model_.buffers.size())
        fail("buffer view " + std::to_string(index) + " refers to buffer " + std::to_string(bv.buffer) +
             ", but the file has " + num(model_.buffers.size()));
    auto const& data = model_.buffers[std::size_t(bv.buffer)].data;
    if (bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset)
        fail("buffer view " + std::to_string(index) + " covers bytes " + num(bv.byteOffset) + " to " +
             std::to_string(std::uint64_t(bv.byteOffset) + bv.byteLength) + " but buffer " + std::to_string(bv.buffer) +
             " holds only " + num(data.size()));
    return {data.data() + bv.byteOffset, bv.byteLength};
}

std::vector<double> ModelReader::read(int index, std::string const& who, int wantComponents) const {
    if (index < 0 || std::size_t(index) >= model_.accessors.size())
        fail(who + " refers to accessor " + std::to_string(index) + ", but the file has " +
             num(model_.accessors.size()));
    auto const& acc = model_.accessors[std::size_t(index)];
    std::string const name = "accessor " + std::to_string(index);
    int const comps = componentCount(acc.type);
    std::size_t const csize = componentSize(acc.componentType);
    if (comps == 0 || csize == 0) fail(name + " has an unknown type or component type");
    if (wantComponents && comps != wantComponents)
        fail(name + " (" + who + ") has " + std::to_string(comps) + " components per element; expected " +
             std::to_string(wantComponents));
    if (acc.count > options_.maxVertices)
        fail(name + " has " + num(acc.count) + " elements, more than the limit of " + num(options_.maxVertices));
    std::size_t const elem = csize * std::size_t(comps);
    std::vector<double> out(acc.count * std::size_t(comps), 0.0);
    if (acc.bufferView >= 0 && acc.count > 0) {
        auto const bytes = bufferView(acc.bufferView, name);
        std::size_t const declared = model_.bufferViews[std::size_t(acc.bufferView)].byteStride;
        std::size_t const stride = declared ? declared : elem;
        if (stride < elem)
            fail("buffer view " + std::to_string(acc.bufferView) + " has byteStride " + num(stride) +
                 ", less than the " + num(elem) + "-byte elements of " + name);
        // 128-bit so that a hostile count or stride cannot wrap around and pass the check.
        unsigned __int128 const end =
            (unsigned __int128)acc.byteOffset + (unsigned __int128)(acc.count - 1) * stride + elem;
        if (end > bytes.size())
            fail(name + " reads bytes up to " +
                 std::to_string(std::uint64_t(std::min<unsigned __int128>(end, UINT64_MAX))) + " but buffer view " +
                 std::to_string(acc.bufferView) + " holds only " + num(bytes.size()));
        for (std::size_t i = 0; i < acc.count; ++i) {
            std::uint8_t const* p = bytes.data() + acc.byteOffset + i * stride;
            for (int c = 0; c < comps; ++c)
                out[i * std::size_t(comps) + std::size_t(c)] =
                    readComponent(p + std::size_t(c) * csize, acc.componentType, acc.normalized);
        }
    }
    if (acc.sparse.isSparse) applySparse(acc, name, comps, csize, out);
    return out;
}

void ModelReader::applySparse(tinygltf::Accessor const& acc, std::string const& name, int comps, std::size_t csize,
                              std::vector<double>& out) const {
    auto const& sp = acc.sparse;
    if (sp.count < 0 || std::size_t(sp.count) > acc.count)
        fail(name + " has " + std::to_string(sp.count) + " sparse values but only " + num(acc.count) + " elements");
    std::size_t const n = std::size_t(sp.count);
    std::size_t const isize = componentSize(sp.indices.componentType);
    if (isize == 0 || sp.indices.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
        sp.indices.componentType == TINYGLTF_COMPONENT_TYPE_SHORT ||
        sp.indices.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT)
        fail(name + " has sparse indices of an invalid component type");
    auto const ib = bufferView(sp.indices.bufferView, name + " sparse indices");
    auto const vb = bufferView(sp.values.bufferView, name + " sparse values");
    std::size_t const elem = csize * std::size_t(comps);
    if (sp.indices.byteOffset < 0 || sp.values.byteOffset < 0 || std::size_t(sp.indices.byteOffset) > ib.size() ||
        n > (ib.size() - std::size_t(sp.indices.byteOffset)) / isize || std::size_t(sp.values.byteOffset) > vb.size() ||
        n > (vb.size() - std::size_t(sp.values.byteOffset)) / elem)
        fail(name + " has sparse data that runs past the end of its buffer views");
    for (std::size_t i = 0; i < n; ++i) {
        double const target =
            readComponent(ib.data() + std::size_t(sp.indices.byteOffset) + i * isize, sp.indices.componentType, false);
        if (target >= double(acc.count))
            fail(name + " has a sparse index " + std::to_string(std::uint64_t(target)) + " past its " + num(acc.count) +
                 " elements");
        std::uint8_t const* p = vb.data() + std::size_t(sp.values.byteOffset) + i * elem;
        for (int c = 0; c < comps; ++c)
            out[std::size_t(target) * std::size_t(comps) + std::size_t(c)] =
                readComponent(p + std::size_t(c) * csize, acc.componentType, acc.normalized);
    }
}

}  // namespace gbl::gltf
