// POSIX write-fsync-rename (the file unnamed until complete where Linux allows); std::ofstream cannot fsync.
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

void write_all(int fd, std::string_view data, const std::filesystem::path& path) {
    while (!data.empty()) {
        const ssize_t n = ::write(fd, data.data(), data.size());
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            fail("cannot write", path, errno);
        data.remove_prefix(static_cast<std::size_t>(n));
    }
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

    void write(std::string_view data) { write_all(fd_, data, path_); }

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

// Writes `contents` to an unnamed file in `path`'s directory (O_TMPFILE) and gives it the
// temporary name only once it is complete and synced, then renames it over `path`: a process
// killed while it writes (SIGKILL, a lost MPI rank's job torn down) leaves no file at all, where a
// named temporary would stay behind half-written. False when the file system has no unnamed files
// (NFS, older kernels): the caller then writes a named temporary.
bool write_unnamed_then_rename(const std::filesystem::path& path, std::string_view contents) {
    const std::filesystem::path dir = path.parent_path().empty() ? "." : path.parent_path();
    const int fd = ::open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0644);
    if (fd < 0)
        return false;
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    write_all(fd, contents, path);
    if (::fsync(fd) != 0)
        fail("cannot sync", path, errno);
    const std::filesystem::path tmp = temporary_path(path);
    const std::string self = "/proc/self/fd/" + std::to_string(fd);
    int linked = ::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, tmp.c_str(), AT_SYMLINK_FOLLOW);
    if (linked != 0 && errno == EEXIST) { // a temporary of an earlier process with this process id
        ::unlink(tmp.c_str());
        linked = ::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, tmp.c_str(), AT_SYMLINK_FOLLOW);
    }
    if (linked != 0) // no /proc, or a file system that cannot name it: the caller writes a named file
        return false;
    if (::rename(tmp.c_str(), path.c_str()) != 0) {
        const int err = errno;
        ::unlink(tmp.c_str());
        fail("cannot rename to", path, err);
    }
    return true;
}

void write_file_atomically(const std::filesystem::path& path, std::string_view contents) {
    if (!write_unnamed_then_rename(path, contents)) {
        TemporaryFile tmp(temporary_path(path));
        tmp.write(contents);
        tmp.commit(path);
    }
    sync_directory(path.parent_path());
}

void publish_file_atomically(const std::filesystem::path& tmp, const std::filesystem::path& path) {
    TemporaryFile file(tmp, true);
    file.commit(path);
    sync_directory(path.parent_path());
}

} // namespace roughgas
