// `roughgas run --checkpoint-every` and `--resume` (src/cli/run_command.cpp, run/checkpoints.cpp):
// checkpoints change no output byte; a checkpoint that is truncated, damaged, of another format or
// program version, of another case, seed or particle count, of another replica, or missing is
// refused with exit 2, naming the file and the reason, and nothing is written; an earlier run's
// checkpoint is never overwritten without --force. Killing and signalling real runs: tests/e2e.
#include "io_test_support.hpp"

#include "roughgas/io/checkpoint_file.hpp"

#include <gtest/gtest.h>

#include <string>

namespace roughgas {
namespace {

namespace fs = std::filesystem;

// Rough constant restitution, 2 replicas, histograms: every output file of a cooling run.
std::string cooling_case(int particles = 2000, double alpha = 0.8) {
    return "[run]\nparticles = " + std::to_string(particles) +
           "\nend = 3.0\noutput_every = 0.5\nreplicas = 2\n" +
           "seed = 7\nhistogram_every = 1.5\nhistogram_bins = 10\n\n[[species]]\nname = \"grain\"\nmass = "
           "1.0\n" +
           "radius = 0.5\n\n[collision]\nmodel = \"constant\"\nalpha = " + std::to_string(alpha) +
           "\nbeta = 0.4\n";
}

std::string shear_case() {
    return "[run]\nkind = \"shear\"\nparticles = 2000\nend = 6.0\noutput_every = 0.5\nreplicas = 2\nseed = "
           "3\n\n"
           "[[species]]\nname = \"grain\"\nmass = 1.0\nradius = 0.5\n\n[collision]\nmodel = \"constant\"\n"
           "alpha = 0.9\nbeta = 0.0\n\n[shear]\nrate = 1.0\n";
}

std::string run_args(const fs::path& f, const fs::path& out, const std::string& extra = "") {
    return "run '" + f.string() + "' --out '" + out.string() + "' --quiet " + extra;
}

void expect_same_outputs(const fs::path& a, const fs::path& b) {
    for (const char* f : {"moments.csv", "histograms.csv", "steady.csv"}) {
        EXPECT_EQ(fs::exists(a / f), fs::exists(b / f)) << f;
        if (fs::exists(a / f)) {
            const std::string x = test::read_file(a / f);
            EXPECT_FALSE(x.empty()) << f;
            EXPECT_TRUE(x == test::read_file(b / f)) << f << " differs between " << a << " and " << b;
        }
    }
}

TEST(ResumeCli, CheckpointsChangeNoOutputByte) {
    const test::ScratchDir dir;
    for (const auto& [name, text] :
         {std::pair{"cooling", cooling_case()}, std::pair{"shear", shear_case()}}) {
        const fs::path f = dir.write(std::string(name) + ".toml", text);
        const fs::path plain = dir / (std::string(name) + "_plain"), ck = dir / (std::string(name) + "_ck");
        ASSERT_EQ(run_roughgas(run_args(f, plain), dir).status, 0);
        const test::CommandResult r =
            run_roughgas(run_args(f, ck, "--checkpoint-every 0.3 --threads 2"), dir);
        ASSERT_EQ(r.status, 0) << r.err;
        expect_same_outputs(plain, ck);
        EXPECT_TRUE(fs::exists(ck / "checkpoint" / "run.bin"));
        EXPECT_TRUE(fs::exists(ck / "checkpoint" / "replica_1.bin"));
        EXPECT_FALSE(fs::exists(plain / "checkpoint")); // none unless asked for (or stopped)
        // Resuming a finished run runs nothing and writes the same files again.
        fs::remove(ck / "moments.csv");
        const test::CommandResult again = run_roughgas("run --resume '" + ck.string() + "' --quiet", dir);
        ASSERT_EQ(again.status, 0) << again.err;
        EXPECT_NE(again.out.find("nothing left to run"), std::string::npos) << again.out;
        expect_same_outputs(plain, ck);
    }
}

TEST(ResumeCli, AnEarlierCheckpointIsKeptWithoutForce) {
    const test::ScratchDir dir;
    const fs::path f = dir.write("c.toml", cooling_case());
    const fs::path out = dir / "out";
    ASSERT_EQ(run_roughgas(run_args(f, out, "--checkpoint-every 1"), dir).status, 0);
    const auto before = test::file_contents(out);
    const test::CommandResult r = run_roughgas(run_args(f, out), dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("checkpoint exists (continue that run with --resume"), std::string::npos) << r.err;
    EXPECT_EQ(test::file_contents(out), before);
    // --force starts over: the old checkpoint goes (this run takes none).
    ASSERT_EQ(run_roughgas(run_args(f, out, "--force"), dir).status, 0);
    EXPECT_FALSE(fs::exists(out / "checkpoint"));
    // --resume takes no case, output directory, overrides, seed or --force.
    for (const char* extra : {"--out x", "--set run.seed=2", "--seed 2", "--force"})
        EXPECT_EQ(run_roughgas("run --resume '" + out.string() + "' " + extra, dir).status, 2) << extra;
}

// A damaged or foreign checkpoint in a copy of a finished checkpointed run.
struct Damage {
    std::string name;
    std::string file;   // under checkpoint/, named in the message
    std::string reason; // in the message
    void (*apply)(const fs::path& ck, const fs::path& other_runs);
};

void PrintTo(const Damage& d, std::ostream* os) {
    *os << d.name;
}

void write(const fs::path& p, const std::string& bytes) {
    std::ofstream(p, std::ios::binary | std::ios::trunc) << bytes;
}

std::vector<Damage> damages() {
    return {
        {"Truncated", "replica_1.bin", "checksum mismatch: the file is truncated or corrupt",
         [](const fs::path& ck, const fs::path&) { fs::resize_file(ck / "replica_1.bin", 100); }},
        {"TruncatedToNothing", "replica_0.bin", "not a roughgas checkpoint",
         [](const fs::path& ck, const fs::path&) { fs::resize_file(ck / "replica_0.bin", 0); }},
        {"OneFlippedByte", "replica_0.bin", "checksum mismatch",
         [](const fs::path& ck, const fs::path&) {
             std::string b = test::read_file(ck / "replica_0.bin");
             b[b.size() / 2] = static_cast<char>(b[b.size() / 2] ^ 1);
             write(ck / "replica_0.bin", b);
         }},
        {"OtherFormatVersion", "run.bin",
         "checkpoint format version 99; this roughgas reads version " +
             std::to_string(checkpoint_format_version),
         [](const fs::path& ck, const fs::path&) {
             std::string b = test::read_file(ck / "run.bin");
             b[8] = 99; // the u64 after the magic
             write(ck / "run.bin", b);
         }},
        {"OtherProgramVersion", "run.bin", "written by roughgas 0.0.1",
         [](const fs::path& ck, const fs::path&) { // re-encoded: a valid file of another roughgas
             RunCheckpoint r = decode_run_checkpoint(test::read_file(ck / "run.bin"));
             r.run.program_version = "0.0.1";
             write(ck / "run.bin", encode_checkpoint(r));
         }},
        {"OtherSeed", "replica_1.bin", "from another run than",
         [](const fs::path& ck, const fs::path& other) {
             fs::copy_file(other / "seed" / "checkpoint" / "replica_1.bin", ck / "replica_1.bin",
                           fs::copy_options::overwrite_existing);
         }},
        {"OtherParticleCount", "replica_0.bin", "3000 particles, expected 2000",
         [](const fs::path& ck, const fs::path& other) {
             fs::copy_file(other / "particles" / "checkpoint" / "replica_0.bin", ck / "replica_0.bin",
                           fs::copy_options::overwrite_existing);
         }},
        {"OtherCase", "replica_0.bin", "another case: line",
         [](const fs::path& ck, const fs::path& other) {
             fs::copy_file(other / "alpha" / "checkpoint" / "replica_0.bin", ck / "replica_0.bin",
                           fs::copy_options::overwrite_existing);
         }},
        {"OtherReplica", "replica_0.bin", "the checkpoint of replica 1, not 0",
         [](const fs::path& ck, const fs::path&) {
             fs::copy_file(ck / "replica_1.bin", ck / "replica_0.bin", fs::copy_options::overwrite_existing);
         }},
        {"RunFileAsReplica", "replica_1.bin", "not a replica's checkpoint",
         [](const fs::path& ck, const fs::path&) {
             fs::copy_file(ck / "run.bin", ck / "replica_1.bin", fs::copy_options::overwrite_existing);
         }},
        {"NoCheckpoint", "run.bin", "no checkpoint (the run was started without --checkpoint-every",
         [](const fs::path& ck, const fs::path&) { fs::remove_all(ck); }},
    };
}

class ResumeRefused : public ::testing::TestWithParam<Damage> {
  protected:
    // One set of finished runs for every case: this one and three of other runs.
    static void SetUpTestSuite() {
        dir_ = new test::ScratchDir(std::string("ResumeRefused"));
        const auto run = [](const std::string& text, const fs::path& out, const std::string& extra) {
            const fs::path f = dir_->write(out.filename().string() + ".toml", text);
            const test::CommandResult r =
                run_roughgas(run_args(f, out, "--checkpoint-every 1 " + extra), *dir_);
            ASSERT_EQ(r.status, 0) << r.err;
        };
        run(cooling_case(), *dir_ / "good", "");
        run(cooling_case(), *dir_ / "other" / "seed", "--seed 8");
        run(cooling_case(3000), *dir_ / "other" / "particles", "");
        run(cooling_case(2000, 0.7), *dir_ / "other" / "alpha", "");
    }
    static void TearDownTestSuite() {
        delete dir_;
        dir_ = nullptr;
    }
    static const test::ScratchDir* dir_;
};
const test::ScratchDir* ResumeRefused::dir_ = nullptr;

TEST_P(ResumeRefused, Exit2NamingFileAndReasonAndWritesNothing) {
    const Damage& d = GetParam();
    const test::ScratchDir dir;
    const fs::path out = dir / "out";
    fs::copy(*dir_ / "good", out, fs::copy_options::recursive);
    d.apply(out / "checkpoint", *dir_ / "other");
    const auto before = test::file_contents(dir.path());
    const test::CommandResult r = run_roughgas("run --resume '" + out.string() + "'", dir);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find((out / "checkpoint" / d.file).string() + ": cannot resume: "), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find(d.reason), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_EQ(test::file_contents(dir.path()), before);
}

INSTANTIATE_TEST_SUITE_P(ResumeCli, ResumeRefused, ::testing::ValuesIn(damages()),
                         [](const ::testing::TestParamInfo<Damage>& info) { return info.param.name; });

TEST(ResumeCli, NoSuchDirectoryIsRefused) {
    const test::ScratchDir dir;
    const test::CommandResult r = run_roughgas("run --resume '" + (dir / "nowhere").string() + "'", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("nowhere: cannot resume: no such directory"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "nowhere"));
}

} // namespace
} // namespace roughgas
