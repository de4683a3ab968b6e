#include <gtest/gtest.h>
#include <toposlam/evaluation/RelationFile.h>
#include <toposlam/io/InputError.h>

#include <TestSupport.h>

#include <fstream>
#include <string>

using namespace toposlam::evaluation;
using toposlam::io::InputError;
using toposlam::test::TempDir;

namespace {

std::string writeFile(const TempDir& dir, const std::string& name, const std::string& text) {
    const std::string path = dir.file(name);
    std::ofstream(path) << text;
    return path;
}

// The InputError message of loading `text` as a relation file ("" if it loads).
std::string loadError(const std::string& text) {
    TempDir dir;
    return toposlam::test::errorOf<InputError>(
        [&] { loadRelations(writeFile(dir, "bad.relations", text)); });
}

}  // namespace

TEST(RelationFile, ReadsTheBenchmarkFormatsAsTheyAre) {
    TempDir dir;
    // intel/fr079 style (6 decimals), mit-csail style (5 decimals, double space before roll),
    // unsorted, and one line with t1 > t2 (6 such lines in intel.relations): kept as written.
    const std::string path = writeFile(
        dir, "mixed.relations",
        "976052905.167303 976052911.885496 -0.056990 -0.128430 0.000000 0.000000 0.000000 "
        "-1.682210\n"
        "1134864645.90321 1134864646.32420 0.31293 0.02935 0.00000  0.00000 0.00000 0.24198\n"
        "\n"
        "976054982.975750 976054982.195045 0.024890 0.066370 0.000000 0.000000 0.000000 "
        "0.549450\r\n");
    const PoseRelations r = loadRelations(path);
    ASSERT_EQ(r.size(), 3u);
    EXPECT_DOUBLE_EQ(r[0].stamp1, 976052905.167303);
    EXPECT_DOUBLE_EQ(r[0].stamp2, 976052911.885496);
    EXPECT_DOUBLE_EQ(r[0].motion.x, -0.056990);
    EXPECT_DOUBLE_EQ(r[0].motion.y, -0.128430);
    EXPECT_DOUBLE_EQ(r[0].motion.phi, -1.682210);
    EXPECT_DOUBLE_EQ(r[1].stamp1, 1134864645.90321);
    EXPECT_DOUBLE_EQ(r[1].motion.phi, 0.24198);
    EXPECT_GT(r[2].stamp1, r[2].stamp2) << "inverse-order relations are not reordered";
    EXPECT_DOUBLE_EQ(r[2].motion.phi, 0.549450);
}

TEST(RelationFile, SaveThenLoadRoundTrips) {
    TempDir dir;
    const PoseRelations in = {{1211.52, 1212.75, {0.5, -0.25, 0.125}},
                              {1300.000001, 1200.5, {-3.0, 2.0, -3.0}}};
    saveRelations(in, dir.file("out.relations"));
    const PoseRelations out = loadRelations(dir.file("out.relations"));
    ASSERT_EQ(out.size(), in.size());
    for (std::size_t i = 0; i < in.size(); ++i) {
        // Stamps are written with 6 decimals (benchmark style), motions with 9.
        EXPECT_NEAR(out[i].stamp1, in[i].stamp1, 5e-7);
        EXPECT_NEAR(out[i].stamp2, in[i].stamp2, 5e-7);
        EXPECT_NEAR(out[i].motion.x, in[i].motion.x, 5e-10);
        EXPECT_NEAR(out[i].motion.y, in[i].motion.y, 5e-10);
        EXPECT_NEAR(out[i].motion.phi, in[i].motion.phi, 5e-10);
    }
}

TEST(RelationFile, CountsLinesThatRepeatAnEarlierOne) {
    // fr079.relations has 4 such lines, mit-csail.relations 1: each is scored again.
    const PoseRelation a{2175.240865, 2231.5813, {0.5, -0.25, 0.125}};
    const PoseRelation b{2175.240865, 2231.5813, {0.5, -0.25, 0.126}};  // another motion
    const PoseRelation c{2231.5813, 2175.240865, {0.5, -0.25, 0.125}};  // the other way round
    EXPECT_EQ(countRepeatedRelations({a, b, c}), 0u);
    EXPECT_EQ(countRepeatedRelations({a, b, a, c, a}), 2u);
    EXPECT_EQ(countRepeatedRelations({}), 0u);
}

TEST(RelationFile, MissingFileIsAnInputError) {
    TempDir dir;
    EXPECT_THROW(loadRelations(dir.file("does-not-exist.relations")), InputError);
}

TEST(RelationFile, MalformedLinesAreInputErrorsWithTheLineNumber) {
    const std::string good = "1 2 0.1 0.2 0 0 0 0.3\n";
    EXPECT_EQ(loadError(good), "");
    EXPECT_NE(loadError(good + "1 2 0.1 0.2 0 0 0\n").find("line 2"), std::string::npos)
        << "7 fields";
    EXPECT_NE(loadError(good + good + "1 2 0.1 0.2 0 0 0 0.3 9\n").find("line 3"),
              std::string::npos)
        << "9 fields";
    EXPECT_NE(loadError(good + "1 2 0.1 abc 0 0 0 0.3\n").find("line 2"), std::string::npos);
    EXPECT_NE(loadError(good + "1 2 0.1 0.2x 0 0 0 0.3\n").find("line 2"), std::string::npos)
        << "trailing garbage in a number";
    EXPECT_NE(loadError(good + "1 2 nan 0.2 0 0 0 0.3\n").find("line 2"), std::string::npos);
    EXPECT_NE(loadError("1 2 0.1 0.2 0.5 0 0 0.3\n").find("line 1"), std::string::npos)
        << "nonzero z: a 3D relation";
    EXPECT_NE(loadError("").find("no relation"), std::string::npos);
    EXPECT_NE(loadError("# only a comment\n\n").find("no relation"), std::string::npos);
}
