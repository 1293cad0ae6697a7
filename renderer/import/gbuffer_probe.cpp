// Checks a manifest's files from their directory entries and headers only, so a device file, a missing
// file or a G-buffer too large is refused in milliseconds rather than after gigabytes of decoding.
#include "import/gbuffer_probe.h"

#include <filesystem>
#include <map>
#include <sstream>

#include "image/image_io.h"

namespace gbl {

namespace fs = std::filesystem;

namespace {

struct Header {
    int width = 0, height = 0, channels = 0;
};

std::string gib(std::uint64_t bytes) {
    std::ostringstream s;
    s.precision(bytes >= (std::uint64_t(10) << 30) ? 0 : 1);
    s << std::fixed << double(bytes) / double(std::uint64_t(1) << 30) << " GiB";
    return s.str();
}

std::optional<Header> header(ImageRef const& ref, std::uintmax_t fileBytes, std::string* error) {
    if (ref.raw) {
        RawFormat const& f = *ref.raw;
        std::uintmax_t const per = f.type == RawType::Float ? 4 : f.type == RawType::Half ? 2 : 1;
        std::uintmax_t const want =
            std::uintmax_t(f.width) * std::uintmax_t(f.height) * std::uintmax_t(f.channels) * per;
        if (fileBytes != want) {
            *error = ref.field + ".raw does not match " + ref.path + ": " + std::to_string(f.width) + "x" +
                     std::to_string(f.height) + " with " + std::to_string(f.channels) + " " +
                     std::string(kRawTypeNames[std::size_t(f.type)]) + " channels needs " + std::to_string(want) +
                     " bytes, the file holds " + std::to_string(fileBytes);
            return std::nullopt;
        }
        return Header{f.width, f.height, f.channels};
    }
    DecodedPixels const probe = probeImageFile(ref.path);
    if (!probe.ok() && !probe.overLimit) {
        *error = ref.field + ".file " + ref.path + " cannot be read (" + probe.error + ")";
        return std::nullopt;
    }
    return Header{probe.width, probe.height, probe.fileChannels};
}

}  // namespace

std::optional<std::string> probeGBufferFiles(std::vector<ImageRef const*> const& refs, std::uint64_t budget) {
    std::map<std::string, Header> seen;
    std::uint64_t bytes = 0;
    ImageRef const* first = nullptr;
    Header frame;
    for (ImageRef const* ref : refs) {
        auto it = seen.find(ref->path);
        if (it == seen.end()) {
            std::error_code ec;
            fs::file_status const st = fs::status(ref->path, ec);
            if (ec || !fs::exists(st))
                return ref->field + ".file " + ref->path + " cannot be read (no such file, or no permission)";
            if (!fs::is_regular_file(st))
                return ref->field + ".file " + ref->path +
                       " is not a regular file (a device, a pipe or a folder): name an image or raw file";
            std::string error;
            auto h = header(*ref, fs::file_size(ref->path, ec), &error);
            if (!h) return error;
            it = seen.emplace(ref->path, *h).first;
            bytes += std::uint64_t(h->width) * std::uint64_t(h->height) * std::uint64_t(h->channels) * 4;
        }
        Header const& h = it->second;
        if (h.width == 0) continue;  // not known before decoding (browser build)
        if (!first) {
            first = ref;
            frame = h;
        } else if (h.width != frame.width || h.height != frame.height) {
            return ref->field + ".file " + ref->path + " is " + std::to_string(h.width) + "x" +
                   std::to_string(h.height) + " but " + first->field + " is " + std::to_string(frame.width) + "x" +
                   std::to_string(frame.height) + ": every attachment must have the frame's size";
        }
        bytes += std::uint64_t(h.width) * std::uint64_t(h.height) * std::uint64_t(ref->channels.size()) * 4;
    }
    if (bytes > budget)
        return "the G-buffer would take " + gib(bytes) + " decoded (" + std::to_string(frame.width) + "x" +
               std::to_string(frame.height) + ", " + std::to_string(refs.size()) + " attachments), over the " +
               gib(budget) + " this program allows: crop or scale the images down";
    return std::nullopt;
}

}  // namespace gbl
