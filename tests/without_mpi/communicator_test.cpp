// The communicator of a build without MPI (ROUGHGAS_MPI=0: CMake found no MPI, or
// -DROUGHGAS_MPI=OFF): a world of one process, and a refusal to run as one of several ranks, which
// would each run the whole job and write the same files. Built from src/parallel/communicator.cpp
// on its own, so that the build with MPI compiles and tests this path too.
#include "roughgas/parallel/communicator.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace roughgas {
namespace {

TEST(CommunicatorWithoutMpi, IsAWorldOfOne) {
    EXPECT_FALSE(built_with_mpi());
    const Communicator c(Launch{});
    EXPECT_EQ(c.rank(), 0);
    EXPECT_EQ(c.size(), 1);
    EXPECT_TRUE(c.is_root());
    EXPECT_FALSE(c.under_launcher());
    const std::vector<std::string> all = c.gather("bytes of rank 0");
    ASSERT_EQ(all.size(), 1u);
    EXPECT_EQ(all[0], "bytes of rank 0");
    EXPECT_EQ(c.max(-7), -7);
}

TEST(CommunicatorWithoutMpi, RefusesToBeOneOfSeveralRanks) {
    Launch several;
    several.by_mpi_launcher = true;
    several.rank = 1;
    several.size = 3;
    EXPECT_THROW(Communicator{several}, std::runtime_error);
    // One rank under a launcher is still a world of one.
    Launch one;
    one.by_mpi_launcher = true;
    EXPECT_EQ(Communicator(one).size(), 1);
}

} // namespace
} // namespace roughgas
