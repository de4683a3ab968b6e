#include <gtest/gtest.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <toposlam/io/AtomicFile.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "TestSupport.h"

namespace fs = std::filesystem;
using toposlam::io::writeFileAtomically;

TEST(AtomicFile, WritesThenRenames) {
    toposlam::test::TempDir dir;
    const std::string out = dir.file("rooms.topo.json");
    writeFileAtomically(out, [](const std::string& tmp) {
        EXPECT_NE(tmp.find(".topo.json"), std::string::npos) << "keeps the extension: " << tmp;
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

namespace {

// A 1 x 1 PNG, IEND chunk last.
const std::vector<unsigned char> kPng = {
    0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A, 0x00, 0x00, 0x00, 0x0D, 0x49, 0x48,
    0x44, 0x52, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x06, 0x00, 0x00,
    0x00, 0x1F, 0x15, 0xC4, 0x89, 0x00, 0x00, 0x00, 0x0A, 0x49, 0x44, 0x41, 0x54, 0x78,
    0x9C, 0x63, 0x00, 0x01, 0x00, 0x00, 0x05, 0x00, 0x01, 0x0D, 0x0A, 0x2D, 0xB4, 0x00,
    0x00, 0x00, 0x00, 0x49, 0x45, 0x4E, 0x44, 0xAE, 0x42, 0x60, 0x82};

void writeBytes(const std::string& file, const std::vector<unsigned char>& bytes, std::size_t n) {
    std::ofstream(file, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(n));
}

// What a library that does not check its writes leaves on a full disk: the first `keep`
// bytes of a gzip stream of 64 KiB.
void writeCutGzip(const std::string& file, double keep) {
    {
        mrpt::io::CFileGZOutputStream gz(file);
        std::string text;
        for (int i = 0; i < 8192; ++i)
            text += std::to_string(i * 7919 % 10007) + " ";
        gz.Write(text.data(), text.size());
    }
    fs::resize_file(file, static_cast<std::uintmax_t>(keep * fs::file_size(file)));
}

// writeFileAtomically(out, write) throws a std::runtime_error naming `out` and containing
// `reason`, and leaves nothing in dir.
void expectRefused(const toposlam::test::TempDir& dir, const std::string& out,
                   const std::function<void(const std::string&)>& write,
                   const std::string& reason) {
    try {
        writeFileAtomically(out, write);
        ADD_FAILURE() << out << " was accepted";
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(out + ": cannot write the file"), std::string::npos) << what;
        EXPECT_NE(what.find(reason), std::string::npos) << what;
    }
    EXPECT_TRUE(fs::is_empty(dir.path())) << "neither the output nor the temporary file remains";
}

}  // namespace

// cv::imwrite and MRPT's gzip stream do not report a write that a full disk cut short: the
// file on disk is checked before it takes the output's name.
TEST(AtomicFile, ATruncatedPngIsNotRenamedIntoPlace) {
    toposlam::test::TempDir dir;
    const std::string out = dir.file("rooms.png");
    writeFileAtomically(out, [](const std::string& tmp) { writeBytes(tmp, kPng, kPng.size()); });
    EXPECT_EQ(fs::file_size(out), kPng.size());
    fs::remove(out);
    expectRefused(
        dir, dir.file("ROOMS.PNG"), [&](const std::string& tmp) { writeBytes(tmp, kPng, 40); },
        "truncated");
    for (const std::size_t cut : {std::size_t{0}, std::size_t{40}, kPng.size() - 1}) {
        SCOPED_TRACE(cut);
        expectRefused(
            dir, out, [&](const std::string& tmp) { writeBytes(tmp, kPng, cut); }, "truncated");
    }
}

TEST(AtomicFile, ATruncatedGzipIsNotRenamedIntoPlace) {
    toposlam::test::TempDir dir;
    const std::string out = dir.file("map.gridmap.gz");
    writeFileAtomically(out, [](const std::string& tmp) { writeCutGzip(tmp, 1.0); });
    EXPECT_TRUE(fs::exists(out));
    fs::remove(out);
    for (const double keep : {0.0, 0.5, 0.99}) {
        SCOPED_TRACE(keep);
        expectRefused(
            dir, out, [&](const std::string& tmp) { writeCutGzip(tmp, keep); }, "truncated");
    }
    // Not gzip at all under a .gz name.
    expectRefused(
        dir, out, [](const std::string& tmp) { std::ofstream(tmp) << "plain text"; }, "truncated");
}

TEST(AtomicFile, AnMrptWriteFailureNamesTheFile) {
    toposlam::test::TempDir dir;
    const std::string out = dir.file("log.rawlog");
    expectRefused(
        dir, out,
        [](const std::string& tmp) {
            std::ofstream(tmp) << "partial";
            throw std::runtime_error(
                "==== MRPT exception ====\nMessage:  Cannot write bytes to stream!\n");
        },
        "(");
}

namespace {

void writeAtomically(const std::string& path, const std::string& text) {
    writeFileAtomically(path, [&](const std::string& tmp) { std::ofstream(tmp) << text; });
}

std::size_t filesIn(const std::string& dir) {
    return static_cast<std::size_t>(
        std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

}  // namespace

TEST(OutputGroup, AFailurePartWayKeepsEveryPreviousFile) {
    using toposlam::io::OutputGroup;
    toposlam::test::TempDir dir;
    const std::string a = dir.file("trajectory.txt"), b = dir.file("map.png");
    writeAtomically(a, "previous run");
    try {
        OutputGroup group;
        writeAtomically(a, "this run");
        EXPECT_EQ(toposlam::test::readFile(a), "previous run") << "renamed only on commit";
        writeFileAtomically(b, [](const std::string&) { throw std::runtime_error("disk full"); });
        group.commit();
        ADD_FAILURE() << "the second write should have thrown";
    } catch (const std::runtime_error&) {
    }
    EXPECT_EQ(toposlam::test::readFile(a), "previous run");
    EXPECT_FALSE(fs::exists(b));
    EXPECT_EQ(filesIn(dir.path()), 1u) << "no temporary file left behind";
}

TEST(OutputGroup, CommitRenamesAllIncludingWritesFromAnotherThread) {
    using toposlam::io::OutputGroup;
    toposlam::test::TempDir dir;
    const std::string a = dir.file("a.txt"), b = dir.file("b.txt");
    OutputGroup group;
    std::thread worker([&] {
        const auto member = group.joinFromThisThread();
        writeAtomically(b, "from the worker");
    });
    worker.join();
    writeAtomically(a, "first");
    writeAtomically(a, "second");  // the later version of a file replaces the earlier one
    EXPECT_FALSE(fs::exists(a));
    EXPECT_FALSE(fs::exists(b));
    group.commit();
    EXPECT_EQ(toposlam::test::readFile(a), "second");
    EXPECT_EQ(toposlam::test::readFile(b), "from the worker");
    EXPECT_EQ(filesIn(dir.path()), 2u);
    writeAtomically(dir.file("c.txt"), "after");  // the group is closed: renamed at once
    EXPECT_TRUE(fs::exists(dir.file("c.txt")));
}

TEST(OutputGroup, AnInnerGroupCommitsIntoTheOuterOne) {
    using toposlam::io::OutputGroup;
    toposlam::test::TempDir dir;
    {
        OutputGroup outer;
        {
            OutputGroup inner;
            writeAtomically(dir.file("inner.txt"), "x");
            inner.commit();
        }
        EXPECT_FALSE(fs::exists(dir.file("inner.txt")));
    }  // the outer group is abandoned
    EXPECT_EQ(filesIn(dir.path()), 0u);
}

TEST(OutputGroup, AFolderInTheWayIsFoundBeforeAnythingIsRenamed) {
    using toposlam::io::OutputGroup;
    toposlam::test::TempDir dir;
    fs::create_directory(dir.file("b.txt"));
    OutputGroup group;
    writeAtomically(dir.file("a.txt"), "x");
    writeAtomically(dir.file("b.txt"), "y");
    try {
        group.commit();
        ADD_FAILURE() << "commit should have thrown";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("b.txt: cannot write the output file (a folder"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_FALSE(fs::exists(dir.file("a.txt")));
}
