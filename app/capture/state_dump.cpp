// Reads the retracer's state dump: JSON with base64 images (PNG for 8-bit, a float PNM for the rest).
#include "capture/state_dump.h"

#include "capture/run_process.h"
#include "image/image_io.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string_view>

namespace gbl::capture {

namespace {

std::string base64Decode(std::string_view in) {
    static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    int table[256];
    std::fill(std::begin(table), std::end(table), -1);
    for (int i = 0; i < 64; ++i) table[static_cast<unsigned char>(kAlphabet[i])] = i;
    std::string out;
    out.reserve(in.size() * 3 / 4);
    unsigned acc = 0;
    int bits = 0;
    for (unsigned char ch : in) {
        if (table[ch] < 0) continue;
        acc = (acc << 6) | unsigned(table[ch]);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out += char((acc >> bits) & 0xff);
        }
    }
    return out;
}

// JSON forbids raw control characters inside strings; the retracer writes shader text with them.
void escapeControlCharacters(std::string& text) {
    std::string out;
    out.reserve(text.size() + text.size() / 50);
    bool inString = false, escaped = false;
    for (char ch : text) {
        if (inString && !escaped && (ch == '\n' || ch == '\r' || ch == '\t')) {
            out += ch == '\n' ? "\\n" : ch == '\r' ? "\\r" : "\\t";
            continue;
        }
        if (inString && !escaped && ch == '\\')
            escaped = true;
        else {
            if (!escaped && ch == '"') inString = !inString;
            escaped = false;
        }
        out += ch;
    }
    text = std::move(out);
}

// The images' base64 text is most of a dump (85 MB for a 1280x720 G-buffer): it is cut out before the
// JSON parser sees it, and "__data__" keeps "#N", the index of its text here.
std::string cutOutImageData(std::string const& text, std::vector<std::string_view>* blobs) {
    static constexpr std::string_view kKey = "\"__data__\": \"";
    std::string out;
    std::size_t pos = 0;
    for (std::size_t k = text.find(kKey); k != std::string::npos; k = text.find(kKey, pos)) {
        std::size_t const begin = k + kKey.size();
        std::size_t const end = text.find('"', begin);
        if (end == std::string::npos) break;
        out.append(text, pos, begin - pos);
        out += "#" + std::to_string(blobs->size());
        blobs->push_back(std::string_view(text).substr(begin, end - begin));
        pos = end;
    }
    out.append(text, pos);
    return out;
}

std::optional<DumpedImage> readDumpedImage(nlohmann::json const& j, std::vector<std::string_view> const& blobs) {
    if (!j.is_object() || j.value("__class__", "") != "image" || !j.contains("__data__")) return std::nullopt;
    DumpedImage d;
    d.format = j.value("__format__", "");
    d.width = j.value("__width__", 0);
    d.height = j.value("__height__", 0);
    std::string const data = j["__data__"].get<std::string>();
    std::size_t const index =
        data.size() > 1 && data[0] == '#' ? std::size_t(std::atoll(data.c_str() + 1)) : blobs.size();
    d.encoded = base64Decode(index < blobs.size() ? blobs[index] : std::string_view(data));
    d.isFloat = d.encoded.size() > 2 && d.encoded[0] == 'P' && std::strchr("FfX", d.encoded[1]);
    return d;
}

}  // namespace

FloatImage DumpedImage::decode() const {
    FloatImage img;
    if (isFloat) {
        // "PF"/"Pf"/"PX" (3, 1, 4 channels), width height, scale; then floats in the machine's order,
        // rows top to bottom (the retracer turns the GL's rows over before writing).
        int const channels = encoded[1] == 'F' ? 3 : encoded[1] == 'f' ? 1 : 4;
        std::size_t pos = 0;
        for (int line = 0; line < 3 && pos != std::string::npos; ++line) pos = encoded.find('\n', pos) + 1;
        std::size_t const count = std::size_t(width) * std::size_t(height) * std::size_t(channels);
        if (pos == 0 || encoded.size() < pos + count * sizeof(float)) return img;
        img.width = width;
        img.height = height;
        img.channels = channels;
        img.pixels.resize(count);
        std::memcpy(img.pixels.data(), encoded.data() + pos, count * sizeof(float));
        return img;
    }
    // The retracer writes PNG for 8-bit targets only (the rest as float PNM above), so the image seam's
    // 8-bit reader from memory loses nothing; it keeps alpha straight (the specular channel, not coverage).
    auto const* bytes = reinterpret_cast<std::uint8_t const*>(encoded.data());
    // No more pixels than the dump's own size says: a PNG of another size is refused undecoded.
    std::size_t const pixels = std::size_t(std::max(width, 0)) * std::size_t(std::max(height, 0));
    DecodedPixels const decoded = decodeImage8({bytes, encoded.size()}, "image/png", pixels);
    if (!decoded.ok() || decoded.bytes.empty()) return img;
    img.width = decoded.width;
    img.height = decoded.height;
    img.channels = decoded.channels;
    img.pixels.resize(decoded.bytes.size());
    for (std::size_t i = 0; i < decoded.bytes.size(); ++i) img.pixels[i] = float(decoded.bytes[i]) / 255.0f;
    return img;
}

std::optional<StateDump> parseStateDump(std::string const& dump, std::string* error) {
    std::vector<std::string_view> blobs;  // views into `dump`, which outlives them
    std::string text = cutOutImageData(dump, &blobs);
    escapeControlCharacters(text);
    nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object()) {
        *error = "the retracer's state dump is not JSON";
        return std::nullopt;
    }
    StateDump s;
    s.uniforms = j.contains("uniforms") ? j["uniforms"] : nlohmann::json::object();
    nlohmann::json const none = nlohmann::json::object();
    auto section = [&](char const* key) -> nlohmann::json const& {
        auto it = j.find(key);
        return it != j.end() && it->is_object() ? *it : none;
    };
    for (auto const& [k, v] : section("shaders").items())
        if (v.is_string()) s.shaders[k] = v.get<std::string>();
    for (auto const& [k, v] : section("textures").items()) {
        // "GL_TEXTURE2, GL_TEXTURE_2D, level = 0": the unit's 2D texture, base level only.
        if (k.find("GL_TEXTURE_2D,") == std::string::npos || k.find("level = 0") == std::string::npos) continue;
        if (auto img = readDumpedImage(v, blobs)) s.textures[std::atoi(k.c_str() + 10)] = std::move(*img);
    }
    for (auto const& [k, v] : section("framebuffer").items())
        if (auto img = readDumpedImage(v, blobs)) s.framebuffer[k] = std::move(*img);
    return s;
}

std::optional<StateDump> dumpState(std::string const& retracer, std::string const& trace, std::uint64_t call,
                                   std::string* error) {
    std::vector<std::pair<std::string, std::string>> env;
    bool const egl = retracer.find("eglretrace") != std::string::npos;
    if (egl) env.emplace_back("WAFFLE_PLATFORM", "surfaceless_egl");  // no display needed
    std::vector<std::string> argv{retracer};
    if (egl) argv.push_back("--headless");
    argv.insert(argv.end(), {"-D", std::to_string(call), "--dump-format=json", trace});
    auto const text = runForOutput(argv, error, env);
    if (!text) return std::nullopt;
    if (text->empty()) {
        *error = retracer + " wrote no state at call " + std::to_string(call);
        return std::nullopt;
    }
    return parseStateDump(*text, error);
}

}  // namespace gbl::capture
