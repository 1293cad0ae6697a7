// Follows framebuffer, draw-buffer and texture-unit state through an `apitrace dump` listing.
#include "capture/trace_scan.h"

#include <set>
#include <sstream>

namespace gbl::capture {

char const* const kScanCallsRegex =
    "^(gl(BindFramebuffer|DrawBuffers|DrawBuffer|NamedFramebufferDrawBuffers|FramebufferTexture|FramebufferTexture2D|"
    "NamedFramebufferTexture|ActiveTexture|BindTexture|BindTextureUnit|Draw[A-Za-z]*|MultiDraw[A-Za-z]*)|"
    "[A-Za-z]*SwapBuffers[A-Za-z]*)$";

namespace {

struct Call {
    std::uint64_t no = 0;
    std::string name;
    std::map<std::string, std::string> args;
};

// "123 glName(a = 1, bufs = {X, Y}) = ret": the top-level "name = value" pairs.
std::optional<Call> parseCall(std::string const& line) {
    std::size_t i = 0;
    while (i < line.size() && std::isdigit(static_cast<unsigned char>(line[i]))) ++i;
    if (i == 0 || i >= line.size() || line[i] != ' ') return std::nullopt;
    Call c;
    c.no = std::stoull(line.substr(0, i));
    std::size_t const open = line.find('(', i);
    if (open == std::string::npos) return std::nullopt;
    c.name = line.substr(i + 1, open - i - 1);
    int depth = 0;
    std::string cur;
    auto flush = [&] {
        std::size_t const eq = cur.find(" = ");
        if (eq != std::string::npos) {
            std::size_t b = cur.find_first_not_of(' ');
            c.args[cur.substr(b, eq - b)] = cur.substr(eq + 3);
        }
        cur.clear();
    };
    for (std::size_t k = open + 1; k < line.size(); ++k) {
        char const ch = line[k];
        if (depth == 0 && ch == ')') break;
        if (ch == '{' || ch == '(' || ch == '[') ++depth;
        if (ch == '}' || ch == ')' || ch == ']') --depth;
        if (depth == 0 && ch == ',')
            flush();
        else
            cur += ch;
    }
    flush();
    return c;
}

unsigned toUnsigned(std::string const& s) {
    try {
        return unsigned(std::stoul(s, nullptr, 0));
    } catch (...) {
        return 0;
    }
}

bool isDraw(std::string const& n) {
    return (n.rfind("glDraw", 0) == 0 && n != "glDrawBuffers" && n != "glDrawBuffer") || n.rfind("glMultiDraw", 0) == 0;
}

}  // namespace

TraceScan scanTrace(std::string const& listing, int frame) {
    TraceScan s;
    unsigned drawFbo = 0;
    std::map<unsigned, int> drawBufferCount;                       // fbo -> colour targets enabled
    std::map<unsigned, std::map<std::string, unsigned>> attached;  // fbo -> attachment -> texture
    std::map<unsigned, unsigned> units;                            // texture unit -> texture
    unsigned activeUnit = 0;
    bool sawGeometry = false;
    bool reached = false;  // a call of the frame asked for was seen
    std::istringstream in(listing);
    for (std::string line; std::getline(in, line);) {
        auto c = parseCall(line);
        if (!c) continue;
        auto arg = [&](char const* k) { return c->args.count(k) ? c->args[k] : std::string(); };
        std::string const& n = c->name;
        reached = reached || s.frames == frame;
        if (n.find("SwapBuffers") != std::string::npos) {
            if (s.frames == frame) break;  // the frame asked for is over
            ++s.frames;
            sawGeometry = false;
            s.lastGeometryDraw.reset();
            continue;
        }
        if (n == "glBindFramebuffer") {
            std::string const t = arg("target");
            if (t == "GL_FRAMEBUFFER" || t == "GL_DRAW_FRAMEBUFFER") drawFbo = toUnsigned(arg("framebuffer"));
        } else if (n == "glDrawBuffers" || n == "glNamedFramebufferDrawBuffers") {
            unsigned const fbo = n == "glDrawBuffers" ? drawFbo : toUnsigned(arg("framebuffer"));
            std::string const bufs = arg("bufs");
            int count = 0;
            for (std::size_t p = bufs.find("GL_COLOR_ATTACHMENT"); p != std::string::npos;
                 p = bufs.find("GL_COLOR_ATTACHMENT", p + 1))
                ++count;
            drawBufferCount[fbo] = count;
        } else if (n == "glDrawBuffer") {
            drawBufferCount[drawFbo] = 1;
        } else if (n.rfind("glFramebufferTexture", 0) == 0 || n == "glNamedFramebufferTexture") {
            unsigned const fbo = n == "glNamedFramebufferTexture" ? toUnsigned(arg("framebuffer")) : drawFbo;
            attached[fbo][arg("attachment")] = toUnsigned(arg("texture"));
        } else if (n == "glActiveTexture") {
            std::string const t = arg("texture");
            activeUnit = t.rfind("GL_TEXTURE", 0) == 0 ? toUnsigned(t.substr(10)) : 0;
        } else if (n == "glBindTexture") {
            units[activeUnit] = toUnsigned(arg("texture"));
        } else if (n == "glBindTextureUnit") {
            units[toUnsigned(arg("unit"))] = toUnsigned(arg("texture"));
        } else if (isDraw(n) && s.frames == frame) {
            auto const counted = drawBufferCount.find(drawFbo);
            if (drawFbo != 0 && counted != drawBufferCount.end() && counted->second >= 2) {
                if (!sawGeometry || s.gbufferFramebuffer != drawFbo) {
                    s.gbufferFramebuffer = drawFbo;
                    s.gbufferAttachments = attached[drawFbo];
                }
                sawGeometry = true;
                s.lastGeometryDraw = c->no;
                continue;
            }
            if (!sawGeometry) continue;
            std::map<std::string, int> sampled;
            for (auto const& [attachment, texture] : s.gbufferAttachments) {
                if (attachment.find("COLOR") == std::string::npos || texture == 0) continue;
                for (auto const& [unit, bound] : units)
                    if (bound == texture) {
                        sampled[attachment] = int(unit);
                        break;
                    }
            }
            if (sampled.size() >= 2) {
                s.lightingDraw = c->no;
                s.sampledAttachments = sampled;
                return s;
            }
        }
    }
    std::string const f = "frame " + std::to_string(frame);
    if (!reached)
        s.error = "the program ended after " + std::to_string(s.frames) + " frame" + (s.frames == 1 ? "" : "s") +
                  ", before " + f + " (frames count from 0): ask for an earlier --frame";
    else if (!sawGeometry)
        s.error = "this frame has no G-buffer: is it a forward renderer? (" + f +
                  " draws into no framebuffer with two or more colour attachments set by glDrawBuffers)";
    else
        s.error = f + " draws a G-buffer (framebuffer " + std::to_string(s.gbufferFramebuffer) +
                  ") but no later draw samples two or more of its attachments: the lighting pass samples nothing of it";
    return s;
}

}  // namespace gbl::capture
