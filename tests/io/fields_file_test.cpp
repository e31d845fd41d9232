// The cell fields' files (io/fields_file.hpp, io/fields_series.hpp): every value, shape, unit and
// attribute read back as written (NaN included), no temporary left behind; the XDMF sidecar lists
// every snapshot with its time and absolute path, escapes the path for XML, and a resumed series
// replaces the rows it writes again and drops those after them.
#include "io_test_support.hpp"

#include "roughgas/io/fields_file.hpp"
#include "roughgas/io/fields_series.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

namespace roughgas {
namespace {

namespace fs = std::filesystem;

CellFields sample(double offset) {
    CellFields f;
    f.cells = {3, 2, 4};
    f.quantities = {FieldQuantity::n, FieldQuantity::u, FieldQuantity::P};
    for (const FieldQuantity q : f.quantities) {
        std::vector<double> v(24 * static_cast<std::size_t>(field_components(q)));
        for (std::size_t k = 0; k < v.size(); ++k)
            v[k] = offset + 0.25 * static_cast<double>(k) + (q == FieldQuantity::P ? 1000 : 0);
        f.values.push_back(v);
    }
    f.values[1][7] = std::numeric_limits<double>::quiet_NaN(); // an empty cell's flow
    return f;
}

std::vector<std::string> names(const fs::path& d) {
    std::vector<std::string> n;
    for (const auto& e : fs::directory_iterator(d))
        n.push_back(e.path().filename().string());
    std::sort(n.begin(), n.end());
    return n;
}

TEST(FieldsFile, ReadsBackWhatWasWritten) {
    const test::ScratchDir dir;
    const CellFields f = sample(0.5);
    FieldsFileHeader h;
    h.t = 12.375;
    h.coll_per_particle = 3.25;
    h.row = 17;
    h.replica = 4;
    h.box = {6.0, 4.0, 8.0};
    h.cells = {3, 2, 4};
    const fs::path p = dir / "x.h5";
    write_fields_file(p, h, f);
    EXPECT_EQ(names(dir.path()), std::vector<std::string>{"x.h5"});
    const FieldsFileHeader r = read_fields_header(p);
    EXPECT_EQ(r.t, h.t);
    EXPECT_EQ(r.coll_per_particle, h.coll_per_particle);
    EXPECT_EQ(r.row, h.row);
    EXPECT_EQ(r.replica, h.replica);
    EXPECT_EQ(r.box, h.box);
    EXPECT_EQ(r.cells, h.cells);
    const std::vector<std::vector<std::size_t>> shapes = {{4, 2, 3}, {4, 2, 3, 3}, {4, 2, 3, 6}};
    const char* units[] = {"1/volume", "length/time", "energy/volume"};
    for (std::size_t k = 0; k < 3; ++k) {
        const FieldsDataset d = read_fields_dataset(p, std::string(field_quantity_names[static_cast<std::size_t>(f.quantities[k])]));
        EXPECT_EQ(d.shape, shapes[k]);
        EXPECT_EQ(d.unit, units[k]);
        ASSERT_EQ(d.values.size(), f.values[k].size());
        for (std::size_t i = 0; i < d.values.size(); ++i)
            if (std::isnan(f.values[k][i]))
                EXPECT_TRUE(std::isnan(d.values[i]));
            else
                EXPECT_EQ(d.values[i], f.values[k][i]);
    }
    EXPECT_THROW(read_fields_dataset(p, "T_rot"), std::runtime_error);
    EXPECT_THROW(read_fields_header(dir / "missing.h5"), std::runtime_error);
    // Written again: the same bytes (no times in the file).
    const std::string first = test::read_file(p);
    write_fields_file(p, h, f);
    EXPECT_TRUE(test::read_file(p) == first);
}

TEST(FieldsSeries, SidecarListsTheSnapshotsAndAResumeReplacesWhatFollows) {
    const test::ScratchDir dir;
    const fs::path run = dir / "run & <co>";
    DomainSpec d;
    d.size = {6.0, 4.0, 12.0};
    d.cells = {3, 2, 4};
    {
        FieldsSeries s(run, 1, d, false);
        for (std::size_t row : {0, 2, 4}) {
            const auto f = std::make_shared<const CellFields>(sample(static_cast<double>(row)));
            s.add(FieldSnapshot{row, 10.0 * static_cast<double>(row), static_cast<double>(row), f});
        }
    }
    const fs::path replica = fields_replica_dir(run, 1);
    EXPECT_EQ(names(replica), (std::vector<std::string>{"row_000000.h5", "row_000002.h5", "row_000004.h5"}));
    EXPECT_EQ(names(fields_dir(run)), (std::vector<std::string>{"replica_1", "replica_1.xmf"}));
    const std::string xdmf = test::read_file(fields_xdmf_path(run, 1));
    // Each file by its path from the sidecar's folder: the run's own path (with XML's special
    // characters) appears nowhere.
    for (const char* row : {"replica_1/row_000000.h5:/n", "replica_1/row_000002.h5:/u", "replica_1/row_000004.h5:/P"})
        EXPECT_NE(xdmf.find(std::string(">") + row + "</DataItem>"), std::string::npos) << row << "\n" << xdmf;
    EXPECT_EQ(xdmf.find("run &amp;"), std::string::npos) << xdmf;
    EXPECT_NE(xdmf.find("<Time Value=\"40\"/>"), std::string::npos);
    EXPECT_NE(xdmf.find("Dimensions=\"5 3 4\""), std::string::npos); // the nodes, z y x
    EXPECT_NE(xdmf.find("Dimensions=\"4 2 3 6\""), std::string::npos); // P, cells z y x, Tensor6
    EXPECT_NE(xdmf.find(">3 2 2</DataItem>"), std::string::npos);   // the spacing, z y x
    // A resumed run writes row 2 again (another time, to tell): rows 0 and 2 remain.
    {
        FieldsSeries s(run, 1, d, true);
        s.add(FieldSnapshot{2, 21.0, 2.0, std::make_shared<const CellFields>(sample(7.0))});
    }
    EXPECT_EQ(names(replica), (std::vector<std::string>{"row_000000.h5", "row_000002.h5"}));
    const std::string resumed = test::read_file(fields_xdmf_path(run, 1));
    EXPECT_NE(resumed.find("<Time Value=\"0\"/>"), std::string::npos);
    EXPECT_NE(resumed.find("<Time Value=\"21\"/>"), std::string::npos);
    EXPECT_EQ(resumed.find("<Time Value=\"20\"/>"), std::string::npos);
    EXPECT_EQ(resumed.find("row_000004"), std::string::npos);
    EXPECT_EQ(read_fields_dataset(replica / "row_000002.h5", "n").values[0], 7.0);
}

// The files are written behind the run: a failure to write reaches the run at the next snapshot
// or at flush, and flush returns only once the files are on disk.
TEST(FieldsSeries, WritesBehindTheRunAndReportsItsErrors) {
    const test::ScratchDir dir;
    DomainSpec d;
    d.size = {6.0, 4.0, 12.0};
    d.cells = {3, 2, 4};
    FieldsSeries s(dir / "run", 0, d, false);
    s.add(FieldSnapshot{0, 0.0, 0.0, std::make_shared<const CellFields>(sample(1.0))});
    s.flush();
    const fs::path replica = fields_replica_dir(dir / "run", 0);
    EXPECT_EQ(read_fields_dataset(replica / "row_000000.h5", "n").values[0], 1.0);
    fs::remove_all(replica); // the next file cannot be created
    s.add(FieldSnapshot{1, 1.0, 1.0, std::make_shared<const CellFields>(sample(2.0))});
    EXPECT_THROW(s.flush(), std::runtime_error);
    s.flush(); // reported once
    EXPECT_THROW(s.add(FieldSnapshot{2, 2.0, 2.0, nullptr}), std::invalid_argument);
}

} // namespace
} // namespace roughgas
