#pragma once
// One writer per output directory. `roughgas run` and `roughgas sweep` hold an exclusive advisory
// lock (flock(2)) on their --out directory for their whole life, so that a second process started
// on the same directory (by hand, or a batch script that reuses a name) is refused with exit status 2
// before it does any work, instead of both rewriting the same CSVs and checkpoint in turn. The lock
// is on the directory itself: no lock file is left behind, and the kernel drops it when the process
// ends however it ends (a kill -9 included), so a stale lock never blocks a later run or --resume.
#include <filesystem>

namespace roughgas::cli {

class OutputDirLock {
  public:
    OutputDirLock() = default;
    ~OutputDirLock();
    OutputDirLock(OutputDirLock&& o) noexcept : fd_(o.fd_) { o.fd_ = -1; }
    OutputDirLock& operator=(OutputDirLock&& o) noexcept;
    OutputDirLock(const OutputDirLock&) = delete;
    OutputDirLock& operator=(const OutputDirLock&) = delete;

    // Locks the existing directory `dir` (`option`: the command-line option that named it, for the
    // message); does nothing if this object already holds a lock. Throws InputError (exit 2) when
    // another process holds it, std::runtime_error when the directory cannot be opened.
    void lock(const std::filesystem::path& dir, const char* option = "--out");
    // The same, but only if `dir` exists already (a new directory is locked once created).
    void lock_if_exists(const std::filesystem::path& dir, const char* option = "--out");
    bool held() const { return fd_ >= 0; }

  private:
    int fd_ = -1;
};

} // namespace roughgas::cli
