// cli::takeOption: an app's own "<flag> <value>" taken out of argv before the rest goes to
// another parser (the Google Benchmark apps).
#include <gtest/gtest.h>
#include <toposlam/cli/CommandLine.h>

#include <string>
#include <vector>

namespace toposlam::cli {
namespace {

TEST(TakeOption, TakesTheFlagAndItsValueOutAndLeavesTheRest) {
    std::vector<std::string> words = {"app", "--benchmark_filter=x", "--data", "/d", "-c", "a.ini"};
    std::vector<char*> argv;
    for (std::string& w : words)
        argv.push_back(w.data());
    int argc = int(argv.size());
    EXPECT_EQ(takeOption(argc, argv.data(), "--data", "fallback"), "/d");
    ASSERT_EQ(argc, 4);
    EXPECT_EQ(std::string(argv[1]), "--benchmark_filter=x");
    EXPECT_EQ(std::string(argv[2]), "-c");
    EXPECT_EQ(std::string(argv[3]), "a.ini");
    EXPECT_EQ(takeOption(argc, argv.data(), "--data", "fallback"), "fallback");
    EXPECT_EQ(argc, 4);
    EXPECT_EQ(takeOption(argc, argv.data(), "-c", "default.ini"), "a.ini");
    EXPECT_EQ(argc, 2);
}

TEST(TakeOption, AFlagWithoutValueIsLeftForTheOtherParser) {
    std::vector<std::string> words = {"app", "--data"};
    std::vector<char*> argv;
    for (std::string& w : words)
        argv.push_back(w.data());
    int argc = int(argv.size());
    EXPECT_EQ(takeOption(argc, argv.data(), "--data", "fallback"), "fallback");
    EXPECT_EQ(argc, 2);  // Google Benchmark then reports it as unrecognized: exit 2
}

}  // namespace
}  // namespace toposlam::cli
