// A zip archive of files stored as they are (method 0, no compression): the browser build's Export
// all hands its folder to the page as one download (issue 29). Plain zip, no zip64: at most 65535
// files and 4 GiB, far above one exported frame.
#pragma once

#include <cstdint>
#include <ctime>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace gbl::ui {

// CRC-32 as zip (and PNG, gzip) use it: polynomial 0xEDB88320, reflected, inverted in and out.
// `crc` continues an earlier call's result over more bytes.
std::uint32_t crc32(std::span<std::uint8_t const> bytes, std::uint32_t crc = 0);

// A time as zip headers store it (MS-DOS): date = (year - 1980) << 9 | month << 5 | day, time =
// hour << 11 | minute << 5 | seconds / 2. Years before 1980 are stored as 1980-01-01.
struct ZipStamp {
    std::uint16_t date = 0x21;  // 1980-01-01
    std::uint16_t time = 0;
};
ZipStamp zipStamp(std::tm const& local);

struct ZipEntry {
    std::string name;  // a relative path with forward slashes, e.g. "export/final.png"
    std::vector<std::uint8_t> data;
};

// The archive's bytes; nullopt with `error` set when a name is empty or absolute, or the archive
// would need zip64.
std::optional<std::vector<std::uint8_t>> zipStored(std::span<ZipEntry const> entries, ZipStamp stamp,
                                                   std::string* error = nullptr);

// Writes every file under `dir` (its subfolders included) into a zip at `zipPath`, each named
// `prefix/` + its path relative to `dir`, in path order, stamped with the current local time.
// nullopt on success, else one sentence naming the file.
std::optional<std::string> zipFolder(std::string const& dir, std::string const& prefix, std::string const& zipPath);

}  // namespace gbl::ui
