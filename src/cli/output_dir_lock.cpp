#include "output_dir_lock.hpp"

#include "roughgas/io/input_error.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace roughgas::cli {

OutputDirLock::~OutputDirLock() {
    if (fd_ >= 0)
        ::close(fd_); // releases the lock
}

OutputDirLock& OutputDirLock::operator=(OutputDirLock&& o) noexcept {
    if (this != &o) {
        if (fd_ >= 0)
            ::close(fd_);
        fd_ = o.fd_;
        o.fd_ = -1;
    }
    return *this;
}

void OutputDirLock::lock(const std::filesystem::path& dir, const char* option) {
    if (fd_ >= 0)
        return;
    const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0)
        throw std::runtime_error(std::string(option) + " " + dir.string() + ": cannot open the directory (" +
                                 std::strerror(errno) + ")");
    int rc;
    do {
        rc = ::flock(fd, LOCK_EX | LOCK_NB);
    } while (rc != 0 && errno == EINTR);
    if (rc != 0) {
        const int err = errno;
        ::close(fd);
        if (err == EWOULDBLOCK)
            throw InputError(dir.string(), option,
                             std::string(option) + " " + dir.string() +
                                 ": another roughgas process is writing into this directory (wait for it "
                                 "to end, or choose another directory)");
        throw std::runtime_error(std::string(option) + " " + dir.string() + ": cannot lock the directory (" +
                                 std::strerror(err) + ")");
    }
    fd_ = fd;
}

void OutputDirLock::lock_if_exists(const std::filesystem::path& dir, const char* option) {
    std::error_code ec;
    if (std::filesystem::is_directory(dir, ec))
        lock(dir, option);
}

} // namespace roughgas::cli
