// cli::NumberRange and cli::NumberArg: the strict number parsing every app's options go through.
#include <toposlam/cli/CommandLine.h>
#include <toposlam/cli/NumberArg.h>

#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <vector>

using namespace toposlam::cli;

TEST(NumberRange, AcceptsOnlyWholeFiniteNumbersInside) {
    const auto r = NumberRange<double>::positive(100);
    EXPECT_EQ(r.parse("0.25"), 0.25);
    EXPECT_EQ(r.parse("100"), 100.0);
    EXPECT_EQ(r.parse("1e1"), 10.0);
    for (const char* bad : {"0", "-1", "100.5", "nan", "NaN", "inf", "-inf", "1e999", "", "abc",
                            "1.5x", "12abc", "1e300", " 1", "1 ", "0x10", "+1"}) {
        EXPECT_FALSE(r.parse(bad)) << bad;
    }
    EXPECT_EQ(r.describe(), "a number in (0, 100]");
}

TEST(NumberRange, CountsNeverWrap) {
    const auto r = NumberRange<unsigned>::closed(2, 100000);
    EXPECT_EQ(r.parse("361"), 361u);
    for (const char* bad : {"-1", "4294967295", "18446744073709551615", "1", "2.0", "1e3",
                            "99999999999999999999999"}) {
        EXPECT_FALSE(r.parse(bad)) << bad;
    }
    const auto all = NumberRange<std::size_t>::nonNegative(1000000000);
    EXPECT_EQ(all.parse("0"), std::size_t{0});
    EXPECT_FALSE(all.parse("-1")) << "-1 is not 'all'";
    EXPECT_EQ(NumberRange<int>::positive(8).describe(), "an integer in [1, 8]");
}

TEST(NumberArg, ParsesChecksAndReportsUsageErrors) {
    const auto parse = [](std::vector<std::string> args, double& value) {
        TCLAP::CmdLine cmd("test", ' ', "1");
        NumberArg<double> time("", "time", "Time.", 1.0, NumberRange<double>::positive(60), "s",
                               cmd);
        args.insert(args.begin(), "app");
        std::vector<char*> argv;
        for (auto& a : args)
            argv.push_back(a.data());
        const auto status = parseCommandLine(cmd, static_cast<int>(argv.size()), argv.data());
        value = time.getValue();
        return status;
    };
    double v = 0;
    EXPECT_EQ(parse({}, v), std::nullopt);
    EXPECT_EQ(v, 1.0) << "the default";
    EXPECT_EQ(parse({"--time", "2.5"}, v), std::nullopt);
    EXPECT_EQ(v, 2.5);
    testing::internal::CaptureStderr();
    EXPECT_EQ(parse({"--time", "-3"}, v), kBadUsage);
    EXPECT_EQ(parse({"--bogus"}, v), kBadUsage);
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("error: --time: '-3' is not a number in (0, 60] (see --help)"),
              std::string::npos)
        << err;
    EXPECT_NE(err.find("error: --bogus: "), std::string::npos) << err;
    // A default outside the range is a programming error, caught at once.
    TCLAP::CmdLine cmd("test", ' ', "1");
    EXPECT_THROW(NumberArg<int>("", "n", "N.", 0, NumberRange<int>::positive(3), "n", cmd),
                 std::logic_error);
}

TEST(ParseNumberList, IsStrictAndAUsageError) {
    EXPECT_EQ(parseNumberList("1.5,-2", 2, "--origin"), (std::vector<double>{1.5, -2}));
    for (const char* bad : {"1", "1,2,3", "1,nan", "1,,2", "a,b", "1e9,0", ""})
        EXPECT_THROW(parseNumberList(bad, 2, "--origin"), UsageError) << bad;
}

TEST(SplitList, KeepsTheItemsAndLeavesOutEmptyOnes) {
    EXPECT_EQ(splitList("a,b,,c,"), (std::vector<std::string>{"a", "b", "c"}));
    EXPECT_TRUE(splitList("").empty());
}

TEST(ParseSeedList, TakesSeedsAndRangesAndIsStrict) {
    EXPECT_EQ(parseSeedList("1-3,7", "--seeds"), (std::vector<unsigned>{1, 2, 3, 7}));
    EXPECT_EQ(parseSeedList("0", "--seeds"), (std::vector<unsigned>{0}));
    for (const char* bad : {"x", "1.5", "-3", "2-x", "1-2-3"}) {
        try {
            parseSeedList(bad, "--seeds");
            ADD_FAILURE() << bad << " was taken";
        } catch (const UsageError& e) {
            EXPECT_EQ(std::string(e.what()).rfind("--seeds: ", 0), 0u) << e.what();
        }
    }
}
