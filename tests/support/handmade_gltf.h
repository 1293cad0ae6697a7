// Handcrafted glTF documents for tests: attribute data packed into one base64 data: buffer.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace gbl::test {

inline std::string base64(std::vector<std::uint8_t> const& bytes) {
    static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t v = std::uint32_t(bytes[i]) << 16;
        if (i + 1 < bytes.size()) v |= std::uint32_t(bytes[i + 1]) << 8;
        if (i + 2 < bytes.size()) v |= bytes[i + 2];
        out += kDigits[(v >> 18) & 63];
        out += kDigits[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? kDigits[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kDigits[v & 63] : '=';
    }
    return out;
}

// One buffer, one buffer view per accessor (4-byte aligned), the rest of the document as JSON.
class HandmadeGltf {
public:
    nlohmann::json doc = {{"asset", {{"version", "2.0"}}}};

    // A float accessor of `type` ("VEC3", "VEC2", ...); returns its index.
    int floats(std::vector<float> const& values, char const* type) {
        std::vector<std::uint8_t> bytes(values.size() * 4);
        std::memcpy(bytes.data(), values.data(), bytes.size());
        return accessor(bytes, 5126, values.size() / components(type), type);
    }
    int indices(std::vector<std::uint32_t> const& values) {
        std::vector<std::uint8_t> bytes(values.size() * 4);
        std::memcpy(bytes.data(), values.data(), bytes.size());
        return accessor(bytes, 5125, values.size(), "SCALAR");
    }
    // Raw bytes in their own buffer view (Draco data, images); returns the view's index.
    int view(std::vector<std::uint8_t> const& bytes) {
        while (data_.size() % 4) data_.push_back(0);
        doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", data_.size()}, {"byteLength", bytes.size()}});
        data_.insert(data_.end(), bytes.begin(), bytes.end());
        return int(doc["bufferViews"].size() - 1);
    }
    // An accessor with no data of its own (Draco-compressed attributes and indices).
    int placeholder(int componentType, std::size_t count, char const* type) {
        doc["accessors"].push_back({{"componentType", componentType}, {"count", count}, {"type", type}});
        return int(doc["accessors"].size() - 1);
    }

    // One node drawing one mesh of the given primitives, in one scene.
    void meshNode(nlohmann::json const& primitives) {
        doc["meshes"].push_back({{"primitives", primitives}});
        doc["nodes"].push_back({{"mesh", doc["meshes"].size() - 1}});
        scene();
    }

    // Any other node (a camera's, say); it joins the scene as a root.
    void node(nlohmann::json const& n) {
        doc["nodes"].push_back(n);
        scene();
    }

    std::vector<std::uint8_t> bytes() {
        nlohmann::json d = doc;
        if (!data_.empty())
            d["buffers"] = {
                {{"byteLength", data_.size()}, {"uri", "data:application/octet-stream;base64," + base64(data_)}}};
        std::string const text = d.dump();
        return {text.begin(), text.end()};
    }

    // The same as binary glTF: the data in the BIN chunk instead of a data: URI.
    std::vector<std::uint8_t> glb() {
        nlohmann::json d = doc;
        std::vector<std::uint8_t> bin = data_;
        while (bin.size() % 4) bin.push_back(0);
        if (!bin.empty()) d["buffers"] = {{{"byteLength", bin.size()}}};
        std::string json = d.dump();
        while (json.size() % 4) json += ' ';
        std::vector<std::uint8_t> out = {'g', 'l', 'T', 'F'};
        auto u32 = [&out](std::size_t v) {
            for (int i = 0; i < 4; ++i) out.push_back(std::uint8_t(v >> (8 * i)));
        };
        u32(2);
        u32(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size()));
        u32(json.size());
        u32(0x4E4F534Au);
        out.insert(out.end(), json.begin(), json.end());
        if (!bin.empty()) {
            u32(bin.size());
            u32(0x004E4942u);
            out.insert(out.end(), bin.begin(), bin.end());
        }
        return out;
    }

private:
    static std::size_t components(std::string const& type) {
        return type == "SCALAR" ? 1 : type == "VEC2" ? 2 : type == "VEC3" ? 3 : 4;
    }
    int accessor(std::vector<std::uint8_t> const& bytes, int componentType, std::size_t count, char const* type) {
        int const v = view(bytes);
        doc["accessors"].push_back(
            {{"bufferView", v}, {"componentType", componentType}, {"count", count}, {"type", type}});
        return int(doc["accessors"].size() - 1);
    }
    void scene() {
        nlohmann::json nodes = nlohmann::json::array();
        for (std::size_t i = 0; i < doc["nodes"].size(); ++i) nodes.push_back(i);
        doc["scenes"] = {{{"nodes", nodes}}};
        doc["scene"] = 0;
    }

    std::vector<std::uint8_t> data_;
};

}  // namespace gbl::test
