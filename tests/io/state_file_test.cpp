// State files (io/state_file.hpp): the encoding gives back every bit of the grains, and a file that
// is truncated anywhere, has a byte flipped, is of another format version or is not a state file is
// refused with a reason.
#include "roughgas/core/bytes.hpp"
#include "roughgas/io/state_file.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <string>

namespace roughgas {
namespace {

const std::vector<StateSpecies> species = {{"light", 1.0, 0.5, 2}, {"heavy", 3.0, 0.8, 1}};

GrainState grains(bool positions) {
    GrainState g;
    if (positions) {
        g.box = {10.0, 20.0, 30.0};
        g.x = {{1.0, 2.0, 3.0}, {4.0, 5.0, 6.0}, {0.0, 19.999999999999996, 29.5}};
    }
    g.t = 123.25;
    g.coll_per_particle = 40.0;
    g.v = {{0.1, -0.2, 0.3}, {-0.0, std::numeric_limits<double>::denorm_min(), 1e300}, {0.1 + 0.2, 7.0, -8.0}};
    g.w = {{1.0, 0.0, 0.0}, {0.0, 2.0, 0.0}, {0.0, 0.0, 3.0}};
    return g;
}

bool same_bits(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0);
}

TEST(StateFile, GivesBackEveryBit) {
    for (const bool positions : {false, true}) {
        const GrainState g = grains(positions);
        const StateFile f = decode_state(encode_state("9.9.9", species, g));
        EXPECT_EQ(f.program_version, "9.9.9");
        EXPECT_EQ(f.species, species);
        EXPECT_EQ(f.grains.box, g.box);
        EXPECT_EQ(f.grains.t, g.t);
        EXPECT_EQ(f.grains.coll_per_particle, g.coll_per_particle);
        EXPECT_TRUE(same_bits(f.grains.x, g.x));
        EXPECT_TRUE(same_bits(f.grains.v, g.v));
        EXPECT_TRUE(same_bits(f.grains.w, g.w));
    }
}

TEST(StateFile, RefusesDamagedFilesWithAReason) {
    const std::string bytes = encode_state("9.9.9", species, grains(true));
    const auto reason = [](const std::string& b) {
        try {
            decode_state(b);
        } catch (const StateFileError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    for (std::size_t n = 0; n < bytes.size(); n += 7)
        EXPECT_NE(reason(bytes.substr(0, n)), "accepted") << "truncated to " << n;
    for (std::size_t i = 16; i < bytes.size(); i += 5) {
        std::string b = bytes;
        b[i] = static_cast<char>(b[i] ^ 0x10);
        EXPECT_NE(reason(b).find("checksum"), std::string::npos) << "byte " << i;
    }
    std::string v = bytes;
    v[8] = 2; // the format version's low byte (little-endian machines; a big-endian one reads another version anyway)
    EXPECT_NE(reason(v).find("format version"), std::string::npos);
    EXPECT_NE(reason("RGCHECKP and more").find("not a roughgas state file"), std::string::npos);
}

} // namespace
} // namespace roughgas
