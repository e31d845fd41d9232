// POSIX write-fsync-rename; std::ofstream cannot fsync.
#include "roughgas/io/atomic_file.hpp"

#include <cerrno>
#include <fcntl.h>
#include <string>
#include <system_error>
#include <unistd.h>

namespace roughgas {
namespace {

[[noreturn]] void fail(const std::string& what, const std::filesystem::path& path, int err) {
    throw std::system_error(err, std::generic_category(), what + " " + path.string());
}

// Closes the descriptor and, unless released, removes the temporary file: every exit path of
// write_file_atomically cleans up.
class TemporaryFile {
  public:
    // `existing`: a file already written, to be synced and renamed (else created empty).
    explicit TemporaryFile(std::filesystem::path path, bool existing = false) : path_(std::move(path)) {
        fd_ = existing ? ::open(path_.c_str(), O_RDONLY | O_CLOEXEC)
                       : ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
        if (fd_ < 0) {
            const int err = errno;
            if (existing)
                ::unlink(path_.c_str());
            fail(existing ? "cannot open" : "cannot create", path_, err);
        }
    }
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;
    ~TemporaryFile() {
        if (fd_ >= 0)
            ::close(fd_);
        if (!renamed_)
            ::unlink(path_.c_str());
    }

    void write(std::string_view data) {
        while (!data.empty()) {
            const ssize_t n = ::write(fd_, data.data(), data.size());
            if (n < 0 && errno == EINTR)
                continue;
            if (n < 0)
                fail("cannot write", path_, errno);
            data.remove_prefix(static_cast<std::size_t>(n));
        }
    }

    // Data on disk before the rename makes it visible, so the new name never shows a partial file.
    void commit(const std::filesystem::path& target) {
        if (::fsync(fd_) != 0)
            fail("cannot sync", path_, errno);
        const int fd = fd_;
        fd_ = -1;
        if (::close(fd) != 0)
            fail("cannot close", path_, errno);
        if (::rename(path_.c_str(), target.c_str()) != 0)
            fail("cannot rename to", target, errno);
        renamed_ = true;
    }

  private:
    std::filesystem::path path_;
    int fd_ = -1;
    bool renamed_ = false;
};

// The rename itself is durable only once the directory entry is synced; best effort (some
// file systems refuse fsync on directories, and the data is already safe).
void sync_directory(const std::filesystem::path& dir) {
    const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
}

} // namespace

std::filesystem::path temporary_path(const std::filesystem::path& path) {
    std::filesystem::path tmp = path;
    tmp += ".tmp." + std::to_string(::getpid());
    return tmp;
}

void write_file_atomically(const std::filesystem::path& path, std::string_view contents) {
    TemporaryFile tmp(temporary_path(path));
    tmp.write(contents);
    tmp.commit(path);
    sync_directory(path.parent_path());
}

void publish_file_atomically(const std::filesystem::path& tmp, const std::filesystem::path& path) {
    TemporaryFile file(tmp, true);
    file.commit(path);
    sync_directory(path.parent_path());
}

} // namespace roughgas
