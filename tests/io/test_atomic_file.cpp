#include <gtest/gtest.h>
#include <toposlam/io/AtomicFile.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "TestSupport.h"

namespace fs = std::filesystem;
using toposlam::io::writeFileAtomically;

TEST(AtomicFile, WritesThenRenames) {
    toposlam::test::TempDir dir;
    const std::string out = dir.file("map.gridmap.gz");
    writeFileAtomically(out, [](const std::string& tmp) {
        EXPECT_NE(tmp.find(".gridmap.gz"), std::string::npos) << "keeps the extension: " << tmp;
        std::ofstream(tmp) << "content";
    });
    std::ifstream in(out);
    std::string s;
    in >> s;
    EXPECT_EQ(s, "content");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator{}), 1);
}

TEST(AtomicFile, FailureLeavesNoFile) {
    toposlam::test::TempDir dir;
    const std::string out = dir.file("traj.txt");
    EXPECT_THROW(writeFileAtomically(out,
                                     [](const std::string& tmp) {
                                         std::ofstream(tmp) << "partial";
                                         throw std::runtime_error("disk full");
                                     }),
                 std::runtime_error);
    EXPECT_TRUE(fs::is_empty(dir.path())) << "neither the output nor the temporary file remains";
}

TEST(AtomicFile, FailureKeepsPreviousVersion) {
    toposlam::test::TempDir dir;
    const std::string out = dir.file("traj.txt");
    std::ofstream(out) << "old";
    EXPECT_THROW(
        writeFileAtomically(out, [](const std::string&) { throw std::runtime_error("bad"); }),
        std::runtime_error);
    std::ifstream in(out);
    std::string s;
    in >> s;
    EXPECT_EQ(s, "old");
}

TEST(AtomicFile, TemporaryOutputFileCommitsOrCleansUp) {
    toposlam::test::TempDir dir;
    {
        toposlam::io::TemporaryOutputFile out(dir.file("log.rawlog.gz"));
        EXPECT_NE(out.temporaryPath().find(".rawlog.gz"), std::string::npos);
        std::ofstream(out.temporaryPath()) << "partial";
    }  // no commit(): removed
    EXPECT_TRUE(fs::is_empty(dir.path()));
    toposlam::io::TemporaryOutputFile out(dir.file("log.rawlog"));
    std::ofstream(out.temporaryPath()) << "complete";
    out.commit();
    EXPECT_TRUE(out.committed());
    EXPECT_TRUE(fs::exists(dir.file("log.rawlog")));
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator{}), 1);
}
