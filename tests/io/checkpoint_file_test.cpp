// Checkpoint files (io/checkpoint_file.hpp): the encoding gives back every bit, and a file that is
// truncated anywhere, has any byte flipped, is of another format version or of the other kind is
// refused with a reason; checkpoint_difference names what differs between two runs.
#include "roughgas/core/bytes.hpp"
#include "roughgas/io/checkpoint_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

namespace roughgas {
namespace {

CheckpointRun a_run() {
    return {"0.1.0", "cases/hcs_rough.toml", {"run.particles=2000", "run.seed=3"}, "[run]\nseed = 3\n", 3, 4,
            2000};
}

ReplicaCheckpoint a_replica() {
    ReplicaCheckpoint c;
    c.run = a_run();
    c.replica = 2;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    c.rows = {{0.0, 0.0, 1.0, nan}, {0.5, 1.0, 0.9, 0.1 + 0.2}};
    HistogramSet h;
    h.t = 0.5;
    h.coll_per_particle = 1.0;
    h.species = {{{0.1, 0.2}, {nan, nan}, {0.3, -0.0}}};
    c.histograms = {h};
    c.state = std::string("\0state\xff bytes", 13);
    return c;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

std::string reason(const std::string& bytes) {
    try {
        decode_replica_checkpoint(bytes);
    } catch (const CheckpointError& e) {
        return e.what();
    }
    return "";
}

TEST(CheckpointFile, RoundTripGivesBackEveryBit) {
    const ReplicaCheckpoint c = a_replica();
    const ReplicaCheckpoint d = decode_replica_checkpoint(encode_checkpoint(c));
    EXPECT_EQ(d.run, c.run);
    EXPECT_EQ(d.replica, 2u);
    ASSERT_EQ(d.rows.size(), 2u);
    EXPECT_TRUE(same_bits(d.rows[0], c.rows[0])); // NaN included
    EXPECT_TRUE(same_bits(d.rows[1], c.rows[1]));
    ASSERT_EQ(d.histograms.size(), 1u);
    EXPECT_EQ(d.histograms[0].t, 0.5);
    EXPECT_TRUE(same_bits(d.histograms[0].species[0].w, c.histograms[0].species[0].w));
    EXPECT_TRUE(std::signbit(d.histograms[0].species[0].cw[1])); // -0.0
    EXPECT_EQ(d.state, c.state);

    const RunCheckpoint r{a_run(), 0.25};
    const RunCheckpoint s = decode_run_checkpoint(encode_checkpoint(r));
    EXPECT_EQ(s.run, r.run);
    EXPECT_EQ(s.checkpoint_every, 0.25);
}

TEST(CheckpointFile, TruncatedAnywhereIsRefused) {
    const std::string bytes = encode_checkpoint(a_replica());
    for (std::size_t n = 0; n < bytes.size(); ++n) {
        const std::string why = reason(bytes.substr(0, n));
        EXPECT_FALSE(why.empty()) << "truncated to " << n << " bytes";
        if (n >= 32) { // the header is whole: the checksum catches it
            EXPECT_NE(why.find("checksum mismatch"), std::string::npos) << n << ": " << why;
        }
    }
    EXPECT_NE(reason(bytes.substr(0, 20)).find("truncated"), std::string::npos);
}

TEST(CheckpointFile, AnyFlippedByteIsRefused) {
    const std::string bytes = encode_checkpoint(a_replica());
    for (std::size_t k = 0; k < bytes.size(); ++k) {
        std::string bad = bytes;
        bad[k] = static_cast<char>(bad[k] ^ 0x10);
        EXPECT_FALSE(reason(bad).empty()) << "byte " << k;
    }
}

TEST(CheckpointFile, OtherVersionOrKindIsNamed) {
    std::string bytes = encode_checkpoint(a_replica());
    bytes[8] = 7; // the format version (after the 8-byte magic), before the checksum is looked at
    EXPECT_NE(reason(bytes).find("checkpoint format version 7; this roughgas reads version " +
                                 std::to_string(checkpoint_format_version)),
              std::string::npos)
        << reason(bytes);
    EXPECT_NE(reason("RGTCACHE and more bytes than a header").find("not a roughgas checkpoint"),
              std::string::npos);
    const std::string run = encode_checkpoint(RunCheckpoint{a_run(), 1.0});
    EXPECT_NE(reason(run).find("not a replica's checkpoint"), std::string::npos) << reason(run);
    EXPECT_THROW(decode_run_checkpoint(encode_checkpoint(a_replica())), CheckpointError);
}

TEST(CheckpointFile, AValidChecksumOverAMalformedPayloadIsRefused) {
    // A payload that ends early, sealed with a correct checksum (a writer bug, not damage).
    ByteWriter w;
    w.raw("RGCHECKP");
    w.u64(checkpoint_format_version);
    w.u64(2);     // a replica file
    w.str("0.1"); // and then nothing
    w.u64(fnv1a(w.bytes().data(), w.size()));
    EXPECT_NE(reason(w.bytes()).find("malformed"), std::string::npos) << reason(w.bytes());
}

TEST(CheckpointFile, DifferenceNamesWhatDiffers) {
    const CheckpointRun a = a_run();
    EXPECT_EQ(checkpoint_difference(a, a), "");
    CheckpointRun b = a;
    b.seed = 4;
    b.particles = 1000;
    b.program_version = "0.2.0";
    b.resolved_case = "[run]\nseed = 4\n";
    const std::string d = checkpoint_difference(b, a);
    EXPECT_NE(d.find("seed 4, expected 3"), std::string::npos) << d;
    EXPECT_NE(d.find("1000 particles, expected 2000"), std::string::npos) << d;
    EXPECT_NE(d.find("written by roughgas 0.2.0, expected 0.1.0"), std::string::npos) << d;
    EXPECT_NE(d.find("line 2 of the resolved case is `seed = 4`, expected `seed = 3`"), std::string::npos)
        << d;
}

TEST(CheckpointFile, Paths) {
    EXPECT_EQ(run_checkpoint_path("out"), std::filesystem::path("out/checkpoint/run.bin"));
    EXPECT_EQ(replica_checkpoint_path("out", 12), std::filesystem::path("out/checkpoint/replica_12.bin"));
}

} // namespace
} // namespace roughgas
