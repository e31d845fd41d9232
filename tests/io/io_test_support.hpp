#pragma once
// Shared helpers of the io tests: a scratch directory per test and running the real binary.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>
#include <sys/wait.h>
#include <unistd.h>

namespace roughgas::test {

namespace fs = std::filesystem;

// A fresh directory named after the running test, removed afterwards.
class ScratchDir {
  public:
    ScratchDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        std::string name = std::string(info->test_suite_name()) + "_" + info->name();
        for (char& c : name) {
            if (!std::isalnum(static_cast<unsigned char>(c)))
                c = '_';
        }
        make(name);
    }
    // Named by the caller: for fixtures shared by a test suite (SetUpTestSuite has no current test).
    explicit ScratchDir(std::string name) { make(name); }
    ~ScratchDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;

    const fs::path& path() const { return path_; }
    fs::path operator/(const std::string& name) const { return path_ / name; }

    // Writes `text` to `name` and returns the path.
    fs::path write(const std::string& name, const std::string& text) const {
        const fs::path p = path_ / name;
        std::ofstream(p) << text;
        return p;
    }

  private:
    void make(const std::string& name) {
        path_ = fs::path(::testing::TempDir()) / ("roughgas_io_" + name + "_" + std::to_string(::getpid()));
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    fs::path path_;
};

inline std::string read_file(const fs::path& p) {
    std::ifstream in(p);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// Every file below `dir` with its bytes: "nothing written" is this map unchanged.
inline std::map<std::string, std::string> file_contents(const fs::path& dir) {
    std::map<std::string, std::string> m;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file())
            m[fs::relative(e.path(), dir).string()] = read_file(e.path());
    return m;
}

// A CSV written by roughgas: column name -> values ('#' lines skipped).
inline std::map<std::string, std::vector<double>> read_csv(const fs::path& p) {
    std::istringstream in(read_file(p));
    std::map<std::string, std::vector<double>> cols;
    std::vector<std::string> names;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#')
            continue;
        std::istringstream fields(line);
        std::vector<std::string> f;
        for (std::string x; std::getline(fields, x, ',');)
            f.push_back(x);
        if (names.empty()) {
            names = f;
            continue;
        }
        for (std::size_t j = 0; j < f.size() && j < names.size(); ++j)
            cols[names[j]].push_back(std::stod(f[j]));
    }
    return cols;
}

struct CommandResult {
    int status = -1;
    std::string out;
    std::string err;
};

// Runs `roughgas ARGS` (ARGS is passed through the shell: quote as needed) in `dir`.
inline CommandResult run_roughgas(const std::string& args, const ScratchDir& dir) {
    const fs::path out = dir / "stdout.txt";
    const fs::path err = dir / "stderr.txt";
    const std::string cmd = std::string("'") + ROUGHGAS_BINARY + "' " + args + " >'" + out.string() +
                            "' 2>'" + err.string() + "'";
    const int raw = std::system(cmd.c_str());
    CommandResult r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = read_file(out);
    r.err = read_file(err);
    fs::remove(out);
    fs::remove(err);
    return r;
}

// A complete, valid case that tabulates fast: ice of Brilliantov et al. (1996) on a 2 x 2 restitution grid.
inline std::string small_case() {
    return R"([run]
particles = 1000
end = 10.0

[[species]]
name = "ice"
mass = 4.188790204786391e-3
radius = 0.01

[collision]
model = "brilliantov"

[material]
young_modulus = 1.0e10
poisson_ratio = 0.3
dissipation = 1.0e-5
friction = 1.0e-3
asperity = 1.0e-6

[restitution]
g_n_min = 0.01
g_n_max = 1.0
g_n_points = 2
g_t_min = 0.01
g_t_max = 1.0
g_t_points = 2
)";
}

// `text` with the first occurrence of `from` replaced by `to` (the test fails if absent).
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos)
        text.replace(at, from.size(), to);
    return text;
}

} // namespace roughgas::test
