// Atomic writes and the CSV writer.
#include "io_test_support.hpp"

#include "roughgas/io/atomic_file.hpp"
#include "roughgas/io/csv_writer.hpp"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <string>
#include <system_error>

namespace roughgas {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> entries(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir))
        names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

TEST(AtomicFile, WritesAndReplacesLeavingNoTemporaryFile) {
    const test::ScratchDir dir;
    const fs::path p = dir / "a.csv";
    write_file_atomically(p, "first\n");
    EXPECT_EQ(test::read_file(p), "first\n");
    write_file_atomically(p, "second, longer\n");
    EXPECT_EQ(test::read_file(p), "second, longer\n");
    EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"a.csv"});
    EXPECT_EQ(temporary_path(p).parent_path(), p.parent_path()); // same file system: rename is atomic
}

TEST(AtomicFile, FailureLeavesTargetAndNoTemporaryFile) {
    const test::ScratchDir dir;
    fs::create_directory(dir / "busy"); // renaming a file over a directory fails
    EXPECT_THROW(write_file_atomically(dir / "busy", "x"), std::system_error);
    EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"busy"});
    EXPECT_THROW(write_file_atomically(dir / "missing" / "a.csv", "x"), std::system_error);
    EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"busy"});
}

TEST(AtomicFile, AProcessKilledWhileWritingLeavesNothing) {
    // A child whose file size limit stops it mid-write (SIGXFSZ ends it as a kill would): neither
    // the target nor a temporary file may be left, and an earlier version of the file stays whole.
    const test::ScratchDir dir;
    {
        const int fd = ::open(dir.path().c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0644);
        if (fd < 0)
            GTEST_SKIP() << "no unnamed files on this file system: a named temporary is written instead";
        ::close(fd);
    }
    const fs::path p = dir / "state.bin";
    write_file_atomically(p, "earlier\n");
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        const rlimit limit{65536, 65536}, no_core{0, 0};
        ::setrlimit(RLIMIT_CORE, &no_core); // SIGXFSZ would leave a core file
        ::setrlimit(RLIMIT_FSIZE, &limit);
        try {
            write_file_atomically(p, std::string(1 << 20, 'x'));
        } catch (...) {
            ::_exit(3); // the write failed without a signal: not what this test looks at
        }
        ::_exit(0);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGXFSZ) << "status " << status;
    EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"state.bin"});
    EXPECT_EQ(test::read_file(p), "earlier\n");
}

TEST(CsvWriter, ProvenanceHeaderAndFullPrecision) {
    CsvProvenance p;
    p.case_file = "cases/ice.toml";
    p.overrides = {"run.seed=3"};
    p.seed = 3;
    p.resolved_case = "[run]\nseed = 3\n\n[contact]\n";
    p.notes = {"a note"};
    CsvWriter w({"g_N", "eps_N"}, p);
    w.add_row({0.1, 1.0 / 3.0});
    w.add_row({3e-300, -2.5});
    EXPECT_THROW(w.add_row({1.0}), std::invalid_argument);
    EXPECT_EQ(w.rows(), 2u);
    const std::string expected_tail = "# resolved case (every default filled in):\n"
                                      "# [run]\n# seed = 3\n#\n# [contact]\n"
                                      "g_N,eps_N\n"
                                      "0.1,0.3333333333333333\n"
                                      "3e-300,-2.5\n";
    const std::string& t = w.text();
    EXPECT_EQ(t.rfind("# roughgas ", 0), 0u) << t;
    EXPECT_NE(t.find("# case: cases/ice.toml\n# set: run.seed=3\n# seed: 3\n# build: "), std::string::npos)
        << t;
    EXPECT_NE(t.find("# a note\n"), std::string::npos);
    ASSERT_GE(t.size(), expected_tail.size());
    EXPECT_EQ(t.substr(t.size() - expected_tail.size()), expected_tail);
    EXPECT_EQ(std::stod("0.3333333333333333"), 1.0 / 3.0); // the shortest decimal reads back exactly
    EXPECT_EQ(std::stod("3e-300"), 3e-300);

    const test::ScratchDir dir;
    w.write(dir / "t.csv");
    EXPECT_EQ(test::read_file(dir / "t.csv"), t);
    EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"t.csv"});
}

} // namespace
} // namespace roughgas
