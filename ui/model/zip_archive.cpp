// Zip's file layout (PKWARE's APPNOTE.TXT, 4.3): per file a local header and its bytes, then the
// central directory (one header per file, pointing at its local header), then the end record.
// Every number is little endian.
#include "model/zip_archive.h"

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

namespace gbl::ui {

namespace fs = std::filesystem;

namespace {

constexpr std::array<std::uint32_t, 256> kCrcTable = [] {
    std::array<std::uint32_t, 256> table{};
    for (std::uint32_t n = 0; n < 256; ++n) {
        std::uint32_t c = n;
        for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
        table[n] = c;
    }
    return table;
}();

constexpr std::uint32_t kLocalHeader = 0x04034b50;
constexpr std::uint32_t kCentralHeader = 0x02014b50;
constexpr std::uint32_t kEndOfCentralDirectory = 0x06054b50;
constexpr std::uint16_t kVersion = 20;        // 2.0, the version of plain stored files and folders
constexpr std::uint16_t kUtf8Names = 0x0800;  // general purpose bit 11: names are UTF-8
constexpr std::uint16_t kStored = 0;          // compression method 0

struct Writer {
    std::vector<std::uint8_t>& out;
    void u16(std::uint16_t v) {
        out.push_back(std::uint8_t(v));
        out.push_back(std::uint8_t(v >> 8));
    }
    void u32(std::uint32_t v) {
        for (int i = 0; i < 4; ++i) out.push_back(std::uint8_t(v >> (8 * i)));
    }
    void bytes(std::span<std::uint8_t const> b) { out.insert(out.end(), b.begin(), b.end()); }
    void text(std::string const& s) { out.insert(out.end(), s.begin(), s.end()); }
};

// The fields a local and a central header share, from "version needed" to "extra field length".
void commonFields(Writer& w, ZipEntry const& e, std::uint32_t crc, ZipStamp stamp) {
    w.u16(kVersion);  // version needed to extract
    w.u16(kUtf8Names);
    w.u16(kStored);
    w.u16(stamp.time);
    w.u16(stamp.date);
    w.u32(crc);
    w.u32(std::uint32_t(e.data.size()));  // compressed size: stored, the same
    w.u32(std::uint32_t(e.data.size()));
    w.u16(std::uint16_t(e.name.size()));
    w.u16(0);  // no extra field
}

}  // namespace

std::uint32_t crc32(std::span<std::uint8_t const> bytes, std::uint32_t crc) {
    crc = ~crc;
    for (std::uint8_t const b : bytes) crc = kCrcTable[(crc ^ b) & 0xFFu] ^ (crc >> 8);
    return ~crc;
}

ZipStamp zipStamp(std::tm const& t) {
    if (t.tm_year < 80) return {};
    return {std::uint16_t((t.tm_year - 80) << 9 | (t.tm_mon + 1) << 5 | t.tm_mday),
            std::uint16_t(t.tm_hour << 11 | t.tm_min << 5 | t.tm_sec / 2)};
}

std::optional<std::vector<std::uint8_t>> zipStored(std::span<ZipEntry const> entries, ZipStamp stamp,
                                                   std::string* error) {
    auto fail = [&](std::string const& why) -> std::optional<std::vector<std::uint8_t>> {
        if (error) *error = why;
        return std::nullopt;
    };
    constexpr std::uint64_t kLimit = std::numeric_limits<std::uint32_t>::max();
    if (entries.size() > std::numeric_limits<std::uint16_t>::max())
        return fail(std::to_string(entries.size()) + " files are more than a zip without zip64 holds (65535)");
    std::uint64_t total = 22;  // the end record
    for (ZipEntry const& e : entries) {
        if (e.name.empty() || e.name.front() == '/' || e.name.find('\\') != std::string::npos)
            return fail("the name '" + e.name + "' is not a relative path with forward slashes");
        if (e.name.size() > std::numeric_limits<std::uint16_t>::max()) return fail("a name is too long for a zip");
        total += 30 + 46 + 2 * std::uint64_t(e.name.size()) + e.data.size();
    }
    if (total > kLimit) return fail("the files are larger than a zip without zip64 holds (4 GiB)");

    std::vector<std::uint8_t> out;
    out.reserve(std::size_t(total));
    Writer w{out};
    std::vector<std::uint32_t> offsets, crcs;
    for (ZipEntry const& e : entries) {
        offsets.push_back(std::uint32_t(out.size()));
        crcs.push_back(crc32(e.data));
        w.u32(kLocalHeader);
        commonFields(w, e, crcs.back(), stamp);
        w.text(e.name);
        w.bytes(e.data);
    }
    std::uint32_t const directory = std::uint32_t(out.size());
    for (std::size_t i = 0; i < entries.size(); ++i) {
        w.u32(kCentralHeader);
        w.u16(kVersion);  // version made by: 2.0 on MS-DOS (no Unix permissions given)
        commonFields(w, entries[i], crcs[i], stamp);
        w.u16(0);  // no comment
        w.u16(0);  // disk 0
        w.u16(0);  // internal attributes
        w.u32(0);  // external attributes
        w.u32(offsets[i]);
        w.text(entries[i].name);
    }
    std::uint32_t const directorySize = std::uint32_t(out.size()) - directory;
    w.u32(kEndOfCentralDirectory);
    w.u16(0);  // this disk
    w.u16(0);  // the disk the directory starts on
    w.u16(std::uint16_t(entries.size()));
    w.u16(std::uint16_t(entries.size()));
    w.u32(directorySize);
    w.u32(directory);
    w.u16(0);  // no comment
    return out;
}

std::optional<std::string> zipFolder(std::string const& dir, std::string const& prefix, std::string const& zipPath) {
    std::error_code ec;
    std::vector<fs::path> files;
    for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec))
        if (it->is_regular_file(ec)) files.push_back(it->path());
    if (ec) return "cannot read the folder " + dir + ": " + ec.message();
    std::sort(files.begin(), files.end());
    std::vector<ZipEntry> entries;
    for (fs::path const& file : files) {
        std::ifstream in(file, std::ios::binary);
        ZipEntry e{prefix + "/" + file.lexically_relative(dir).generic_string(),
                   std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), {})};
        if (!in.good() && !in.eof()) return "cannot read " + file.string();
        entries.push_back(std::move(e));
    }
    std::time_t const now = std::time(nullptr);
    std::tm local{};
    if (std::tm const* t = std::localtime(&now)) local = *t;
    std::string why;
    std::optional<std::vector<std::uint8_t>> const bytes = zipStored(entries, zipStamp(local), &why);
    if (!bytes) return "cannot write " + zipPath + ": " + why;
    std::ofstream out(zipPath, std::ios::binary);
    out.write(reinterpret_cast<char const*>(bytes->data()), std::streamsize(bytes->size()));
    out.close();
    if (!out) return "cannot write " + zipPath;
    return std::nullopt;
}

}  // namespace gbl::ui
