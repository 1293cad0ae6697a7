// The stored zip writer (model/zip_archive.h): CRC-32 against its published check values, and an
// archive read back header by header as an unzip program reads it (end record, central directory,
// local headers), every name, size, CRC and byte compared.
#include "model/zip_archive.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

using namespace gbl::ui;
namespace fs = std::filesystem;

namespace {

std::vector<std::uint8_t> bytesOf(std::string const& s) {
    return {s.begin(), s.end()};
}

std::uint32_t u16(std::vector<std::uint8_t> const& b, std::size_t at) {
    return std::uint32_t(b.at(at)) | std::uint32_t(b.at(at + 1)) << 8;
}
std::uint32_t u32(std::vector<std::uint8_t> const& b, std::size_t at) {
    return u16(b, at) | u16(b, at + 2) << 16;
}

struct ReadEntry {
    std::string name;
    std::vector<std::uint8_t> data;
    std::uint32_t crc = 0;
    std::uint32_t date = 0, time = 0;
};

// Reads an archive of stored files as APPNOTE.TXT describes: the end record is the last 22 bytes
// (no comment), it locates the central directory, each central header locates its local header.
std::vector<ReadEntry> readZip(std::vector<std::uint8_t> const& zip) {
    std::vector<ReadEntry> entries;
    EXPECT_GE(zip.size(), 22u);
    if (zip.size() < 22) return entries;
    std::size_t const end = zip.size() - 22;
    EXPECT_EQ(u32(zip, end), 0x06054b50u);
    std::uint32_t const count = u16(zip, end + 10);
    EXPECT_EQ(u16(zip, end + 8), count);
    std::size_t at = u32(zip, end + 16);
    EXPECT_EQ(at + u32(zip, end + 12), end);  // the directory ends where the end record starts
    for (std::uint32_t i = 0; i < count; ++i) {
        EXPECT_EQ(u32(zip, at), 0x02014b50u);
        EXPECT_EQ(u16(zip, at + 10), 0u);  // stored
        ReadEntry e;
        e.crc = u32(zip, at + 16);
        std::uint32_t const size = u32(zip, at + 24);
        EXPECT_EQ(u32(zip, at + 20), size);  // stored: compressed size = size
        std::uint32_t const nameLength = u16(zip, at + 28);
        std::uint32_t const extra = u16(zip, at + 30), comment = u16(zip, at + 32);
        std::size_t const local = u32(zip, at + 42);
        e.name.assign(zip.begin() + std::ptrdiff_t(at + 46), zip.begin() + std::ptrdiff_t(at + 46 + nameLength));
        e.time = u16(zip, at + 12);
        e.date = u16(zip, at + 14);
        // The local header repeats what the directory says.
        EXPECT_EQ(u32(zip, local), 0x04034b50u);
        EXPECT_EQ(u32(zip, local + 14), e.crc);
        EXPECT_EQ(u32(zip, local + 22), size);
        EXPECT_EQ(u16(zip, local + 26), nameLength);
        std::size_t const data = local + 30 + nameLength + u16(zip, local + 28);
        EXPECT_EQ(std::string(zip.begin() + std::ptrdiff_t(local + 30),
                              zip.begin() + std::ptrdiff_t(local + 30 + nameLength)),
                  e.name);
        EXPECT_LE(data + size, zip.size());
        if (data + size > zip.size()) return entries;
        e.data.assign(zip.begin() + std::ptrdiff_t(data), zip.begin() + std::ptrdiff_t(data + size));
        entries.push_back(std::move(e));
        at += 46 + nameLength + extra + comment;
    }
    return entries;
}

}  // namespace

TEST(ZipArchive, Crc32MatchesItsCheckValues) {
    // The standard check value of CRC-32 (ISO-HDLC), and two more published ones.
    EXPECT_EQ(crc32(bytesOf("123456789")), 0xCBF43926u);
    EXPECT_EQ(crc32(bytesOf("The quick brown fox jumps over the lazy dog")), 0x414FA339u);
    EXPECT_EQ(crc32({}), 0u);
    std::vector<std::uint8_t> const zeros(32, 0);
    EXPECT_EQ(crc32(zeros), 0x190A55ADu);
    // Continued over two parts, the same as over the whole.
    std::vector<std::uint8_t> const all = bytesOf("123456789");
    EXPECT_EQ(crc32(std::span(all).subspan(4), crc32(std::span(all).first(4))), 0xCBF43926u);
}

TEST(ZipArchive, StampIsMsDosDateAndTime) {
    std::tm t{};
    t.tm_year = 2024 - 1900;
    t.tm_mon = 2;  // March
    t.tm_mday = 5;
    t.tm_hour = 14;
    t.tm_min = 30;
    t.tm_sec = 21;
    ZipStamp const s = zipStamp(t);
    EXPECT_EQ(s.date, (44u << 9) | (3u << 5) | 5u);
    EXPECT_EQ(s.time, (14u << 11) | (30u << 5) | 10u);  // two-second steps
    t.tm_year = 70;                                     // before 1980: the earliest date a zip holds
    EXPECT_EQ(zipStamp(t).date, 0x21u);
}

TEST(ZipArchive, EveryEntryReadsBack) {
    std::vector<std::uint8_t> binary;
    for (int i = 0; i < 1000; ++i) binary.push_back(std::uint8_t(i * 7 + 3));
    std::vector<ZipEntry> const entries = {
        {"export/final.png", binary}, {"export/empty.json", {}}, {"export/sub/stats.json", bytesOf("{\"a\": 1}\n")}};
    ZipStamp const stamp{0x5865, 0x73CA};
    auto const zip = zipStored(entries, stamp);
    ASSERT_TRUE(zip);
    std::vector<ReadEntry> const read = readZip(*zip);
    ASSERT_EQ(read.size(), entries.size());
    for (std::size_t i = 0; i < entries.size(); ++i) {
        EXPECT_EQ(read[i].name, entries[i].name);
        EXPECT_EQ(read[i].data, entries[i].data);
        EXPECT_EQ(read[i].crc, crc32(entries[i].data));
        EXPECT_EQ(read[i].date, stamp.date);
        EXPECT_EQ(read[i].time, stamp.time);
    }
    EXPECT_EQ(read[2].crc, 0x5C47A1FAu);  // as Python's zlib.crc32 gives for these bytes
    // An empty archive is the end record alone.
    auto const empty = zipStored({}, stamp);
    ASSERT_TRUE(empty);
    EXPECT_EQ(empty->size(), 22u);
    EXPECT_TRUE(readZip(*empty).empty());
}

TEST(ZipArchive, RefusesNamesThatAreNotRelativePaths) {
    std::string why;
    for (char const* name : {"", "/etc/passwd", "export\\final.png"}) {
        std::vector<ZipEntry> const entries = {{name, {}}};
        EXPECT_FALSE(zipStored(entries, {}, &why)) << name;
        EXPECT_NE(why.find("relative path"), std::string::npos) << why;
    }
}

TEST(ZipArchive, FolderIsZippedWithItsSubfoldersInPathOrder) {
    fs::path const dir = fs::temp_directory_path() / "gbl_zip_folder";
    fs::remove_all(dir);
    fs::create_directories(dir / "textures");
    auto write = [&](fs::path const& rel, std::string const& text) {
        std::ofstream(dir / rel, std::ios::binary) << text;
    };
    write("b.txt", "second");
    write("a.txt", "first");
    write("textures/c.png", std::string("\x89PNG\0\r\n", 7));
    fs::path const zipPath = fs::temp_directory_path() / "gbl_zip_folder.zip";
    ASSERT_EQ(zipFolder(dir.string(), "export", zipPath.string()), std::nullopt);
    std::ifstream in(zipPath, std::ios::binary);
    std::vector<std::uint8_t> const zip{std::istreambuf_iterator<char>(in), {}};
    std::vector<ReadEntry> const read = readZip(zip);
    ASSERT_EQ(read.size(), 3u);
    EXPECT_EQ(read[0].name, "export/a.txt");
    EXPECT_EQ(read[0].data, bytesOf("first"));
    EXPECT_EQ(read[1].name, "export/b.txt");
    EXPECT_EQ(read[2].name, "export/textures/c.png");
    EXPECT_EQ(read[2].data.size(), 7u);
    EXPECT_EQ(read[2].data[4], 0u);  // binary bytes, a zero among them, kept
    // A folder that is not there: one sentence naming it.
    auto const missing = zipFolder((dir / "missing").string(), "x", zipPath.string());
    ASSERT_TRUE(missing);
    EXPECT_NE(missing->find("missing"), std::string::npos);
    fs::remove_all(dir);
    fs::remove(zipPath);
}
