#pragma once
// The real roughgas binary as a child process that a test can signal and kill: started with
// posix_spawn, not through a shell (a shell's background job would have SIGINT ignored), with
// SIGINT and SIGTERM at their defaults and unblocked whatever the test runner set.
#include "../io/io_test_support.hpp"

#include <gtest/gtest.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <ctime>
#include <fcntl.h>
#include <filesystem>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <vector>

extern char** environ;

namespace roughgas::test {

class ChildProcess {
  public:
    // Runs ROUGHGAS_BINARY with `args`, stdout and stderr to the files `out` and `err`.
    ChildProcess(const std::vector<std::string>& args, const std::filesystem::path& out,
                 const std::filesystem::path& err)
        : ChildProcess(ROUGHGAS_BINARY, args, out, err) {}
    // Runs `program` (a path) with `args`; with `own_group`, in a process group of its own, whose
    // id is the child's pid (a terminal's foreground job: signal_group() signals it as Ctrl-C does).
    ChildProcess(const std::string& program, const std::vector<std::string>& args,
                 const std::filesystem::path& out, const std::filesystem::path& err, bool own_group = false) {
        std::vector<std::string> all{program};
        all.insert(all.end(), args.begin(), args.end());
        std::vector<char*> argv;
        for (std::string& a : all)
            argv.push_back(a.data());
        argv.push_back(nullptr);
        posix_spawn_file_actions_t files;
        posix_spawn_file_actions_init(&files);
        posix_spawn_file_actions_addopen(&files, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        posix_spawn_file_actions_addopen(&files, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        posix_spawnattr_t attr;
        posix_spawnattr_init(&attr);
        sigset_t none, defaults;
        sigemptyset(&none);
        sigemptyset(&defaults);
        sigaddset(&defaults, SIGINT);
        sigaddset(&defaults, SIGTERM);
        posix_spawnattr_setsigmask(&attr, &none);
        posix_spawnattr_setsigdefault(&attr, &defaults);
        posix_spawnattr_setpgroup(&attr, 0);
        posix_spawnattr_setflags(&attr, static_cast<short>(POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF |
                                                           (own_group ? POSIX_SPAWN_SETPGROUP : 0)));
        const int e = posix_spawn(&pid_, program.c_str(), &files, &attr, argv.data(), environ);
        posix_spawn_file_actions_destroy(&files);
        posix_spawnattr_destroy(&attr);
        if (e != 0) {
            ADD_FAILURE() << "posix_spawn: " << e;
            pid_ = -1;
        }
    }
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;
    ~ChildProcess() {
        if (pid_ > 0 && !done_) { // a failed test must not leave a run behind
            ::kill(pid_, SIGKILL);
            wait();
        }
    }

    void signal(int sig) const {
        if (pid_ > 0 && !done_)
            ::kill(pid_, sig);
    }
    // `sig` to every process of the child's group (the child made with `own_group`).
    void signal_group(int sig) const {
        if (pid_ > 0 && !done_)
            ::kill(-pid_, sig);
    }
    // The raw wait status (WIFEXITED, WIFSIGNALED, ...).
    int wait() {
        if (!done_ && pid_ > 0) {
            while (::waitpid(pid_, &status_, 0) < 0 && errno == EINTR) {
            }
            done_ = true;
        }
        return status_;
    }
    bool running() {
        if (done_ || pid_ <= 0)
            return false;
        if (::waitpid(pid_, &status_, WNOHANG) == pid_)
            done_ = true;
        return !done_;
    }

  private:
    pid_t pid_ = -1;
    int status_ = -1;
    bool done_ = false;
};

// Polls every millisecond until `ready()` or the child has ended or `limit` has passed: returns
// whether `ready()` held. The limit is generous (a loaded CI machine); no result depends on timing.
template <class Ready>
bool wait_until(ChildProcess& child, Ready&& ready, std::chrono::seconds limit = std::chrono::seconds(120)) {
    const auto end = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < end) {
        if (ready())
            return true;
        if (!child.running())
            return ready();
        struct timespec ms {
            0, 1000000
        };
        nanosleep(&ms, nullptr);
    }
    return false;
}

// `roughgas args...` (stdout and stderr into files in `dir`) signalled with `sig` once `ready()`
// holds; with `twice`, signalled again once it has said it is stopping. Its status and stderr.
struct Stopped {
    int status = -1;
    std::string err;
};
template <class Ready>
Stopped start_and_stop(const std::vector<std::string>& args, int sig, Ready&& ready, const ScratchDir& dir,
                       bool twice = false) {
    ChildProcess child(args, dir / "child_out.txt", dir / "child_err.txt");
    EXPECT_TRUE(wait_until(child, ready)) << read_file(dir / "child_err.txt");
    child.signal(sig);
    if (twice) { // once the first is taken (the message is out), a second one ends it at once
        wait_until(child,
                   [&] { return read_file(dir / "child_err.txt").find("stopping") != std::string::npos; });
        child.signal(sig);
    }
    Stopped s;
    s.status = child.wait();
    s.err = read_file(dir / "child_err.txt");
    return s;
}

} // namespace roughgas::test
