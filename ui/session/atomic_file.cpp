// Atomic replace of a file: temporary file in the same directory, fsync, rename, fsync of the directory.
#include "session/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace gbl::ui {

namespace fs = std::filesystem;

namespace {

std::string failure(std::string const& path, char const* step, int err) {
    return "cannot write " + path + ": " + step + " failed (" + std::strerror(err) + ")";
}

// Closes the descriptor and deletes the temporary file unless the write went through.
struct TempFile {
    int fd = -1;
    std::string path;
    bool keep = false;
    ~TempFile() {
        if (fd >= 0) ::close(fd);
        if (!keep && !path.empty()) ::unlink(path.c_str());
    }
};

}  // namespace

std::optional<std::string> writeFileAtomically(std::string const& path, std::string_view contents) {
    fs::path const target(path);
    if (target.filename().empty()) return "cannot write '" + path + "': it names a directory, not a file";
    fs::path const dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::error_code ec;
    if (fs::is_directory(target, ec)) return "cannot write " + path + ": it is a directory";

    // The temporary name must live in the same directory: rename() is only atomic within one
    // file system, and a reader must never find the target missing or half written.
    // open() with 0666 rather than mkstemp (0600): the file gets the permissions the umask
    // gives any new document. O_EXCL plus pid and a counter keep concurrent writers apart.
    static std::atomic<unsigned> counter{0};
    TempFile tmp;
    for (int attempt = 0; tmp.fd < 0; ++attempt) {
        // Appended: "." + string trips GCC 12 -O3's -Wrestrict (a false positive inside std::string).
        std::string name = ".";
        name += target.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                std::to_string(counter.fetch_add(1));
        tmp.path = (dir / name).string();
        tmp.fd = ::open(tmp.path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (tmp.fd < 0) {
            int const err = errno;
            tmp.path.clear();
            if (err != EEXIST || attempt > 100) return failure(path, "creating a temporary file in its directory", err);
        }
    }

    char const* data = contents.data();
    std::size_t left = contents.size();
    while (left > 0) {
        ssize_t const n = ::write(tmp.fd, data, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            return failure(path, "writing", errno);
        }
        data += n;
        left -= std::size_t(n);
    }
    if (::fsync(tmp.fd) != 0) return failure(path, "fsync", errno);
    if (::close(tmp.fd) != 0) {
        tmp.fd = -1;
        return failure(path, "closing", errno);
    }
    tmp.fd = -1;
    if (::rename(tmp.path.c_str(), path.c_str()) != 0) return failure(path, "renaming the temporary file", errno);
    tmp.keep = true;

    // The rename itself lives in the directory: sync it so a power cut cannot undo it.
    int const dirFd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
    if (dirFd >= 0) {
        ::fsync(dirFd);
        ::close(dirFd);
    }
    return std::nullopt;
}

std::optional<std::string> readWholeFile(std::string const& path, std::string* error) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
        *error = path + " is a directory, not a file";
        return std::nullopt;
    }
    std::ifstream f(path, std::ios::binary);
    if (!f) {
        *error = "cannot open " + path + ": " + std::strerror(errno);
        return std::nullopt;
    }
    std::ostringstream s;
    s << f.rdbuf();
    if (f.bad()) {
        *error = "cannot read " + path;
        return std::nullopt;
    }
    return s.str();
}

}  // namespace gbl::ui
