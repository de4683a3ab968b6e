// Every .ini file of config_ini/ through the app that reads it, spoilt three ways: garbage
// bytes, a misspelled key, bad values (not a number, NaN, out of range). Each must end in a
// clear "error: <file>: ..." on stderr, exit status 1 and no output file; the unspoilt file
// must work. Every key and bad value is checked in process, a sample through the apps. Sections
// passed through to MRPT ([ICP], icp-slam's [MappingApplication]) are MRPT's to read and are only
// spoilt with garbage. Not here yet: rooms.ini (RoomSegmenter's options are not config::Options
// yet); the icp-slam / kf-slam files are read by MRPT's apps.
#include <gtest/gtest.h>
#include <toposlam/config/ConfigError.h>
#include <toposlam/config/IniFile.h>

#include <TestSupport.h>
#include "OptionsTable.h"

#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <random>
#include <sstream>

namespace {

using namespace toposlam;
namespace fs = std::filesystem;

/// How an app reads one config_ini file: its arguments to read `section` (with {ini} and
/// {out} replaced by the spoilt file and the output file).
struct IniUse {
    std::string file, app;
    std::function<std::string(const std::string& section)> args;
};

std::string share() {
    return test::shareDir();
}

std::vector<IniUse> iniUses(const test::TempDir& dir) {
    {
        // Three poses of share/office's tour: a short simulation that succeeds.
        std::ifstream gt(share() + "/office/office_gt.txt");
        std::ofstream poses(dir.file("poses.txt"));
        std::string line;
        while (std::getline(gt, line) && line.rfind('#', 0) == 0) {
        }
        for (int i = 0; i < 3 && gt; ++i, std::getline(gt, line))
            poses << line << "\n";
    }
    const std::string office = "'" + share() + "/office/";
    const auto fixed = [](const std::string& args) {
        return [args](const std::string&) { return args; };
    };
    const auto annotate = [office](const std::string& section) {
        const std::string method = section == "SegmentExtractor"         ? "segments"
                                   : section == "SplitAndMergeExtractor" ? "split-merge"
                                                                         : "corners";
        return office + "office.rawlog' --max-scans 3 -q -c {ini} -o {out} -e " + method;
    };
    const std::string matching = "-s 1 -l '' --no-guess-run -e split-merge -c {ini} -j {out}";
    // A three-scan log for toposlam-slam.
    const std::string log = dir.file("three.rawlog");
    const auto sim =
        test::runApp("toposlam-sim", office + "office.gridmap.gz' --poses '" +
                                         dir.file("poses.txt") + "' -q -o '" + log + "'");
    EXPECT_EQ(sim.exitCode, 0) << sim.output;
    return {
        {"features.ini", "toposlam-annotate-features", annotate},
        {"graph-matcher.ini", "toposlam-bench-matching", fixed(matching)},
        {"bench-matching-icp.ini", "toposlam-bench-matching", fixed(matching)},
        {"toposlam-slam.ini", "toposlam-slam", fixed("{ini} '" + log + "' -o {out}")},
        {"sim-office.ini", "toposlam-sim",
         fixed(office + "office.gridmap.gz' --poses '" + dir.file("poses.txt") +
               "' -q -c {ini} -o {out}")},
    };
}

std::string replaced(std::string s, const std::string& what, const std::string& with) {
    for (std::size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + with.size()))
        s.replace(p, what.size(), with);
    return s;
}

/// Runs `use` on `iniText`; returns the output, checks exit status and output file.
std::string runWith(const IniUse& use, const std::string& iniText, bool expectSuccess,
                    const test::TempDir& dir, const std::string& section = "") {
    const std::string ini = dir.file("spoilt-" + use.file), out = dir.file("out");
    fs::create_directory(out);
    std::ofstream(ini, std::ios::binary) << iniText;
    const std::string outFile = out + (use.app == "toposlam-bench-matching" ? "/out.json"
                                       : use.app == "toposlam-slam"         ? "/slam-out"
                                                                            : "/out.rawlog");
    const std::string args = replaced(replaced(use.args(section), "{ini}", "'" + ini + "'"),
                                      "{out}", "'" + outFile + "'");
    const auto r = test::runApp(use.app, args);
    std::size_t left = 0;
    for (const auto& e : fs::directory_iterator(out)) {
        (void)e;
        ++left;
    }
    if (expectSuccess) {
        EXPECT_EQ(r.exitCode, 0) << use.app << " " << args << "\n" << r.output;
        EXPECT_TRUE(fs::exists(outFile)) << use.app << " " << args;
    } else {
        EXPECT_EQ(r.exitCode, 1) << use.app << " " << args << "\n"
                                 << r.output << "\nfile:\n"
                                 << iniText.substr(0, 2000);
        EXPECT_NE(r.output.find("error: " + ini + ": "), std::string::npos)
            << use.app << " " << args << "\n"
            << r.output;
        EXPECT_EQ(left, 0u) << use.app << " left a file behind: " << args;
    }
    fs::remove_all(out);
    return r.output;
}

using test::readFile;

/// The text with `key = ...` of [section] replaced by `line` (the first such line), or with
/// `line` added at the top of the section when the file does not spell the key out.
std::string withLine(const std::string& text, const std::string& section, const std::string& key,
                     const std::string& line) {
    std::istringstream in(text);
    std::ostringstream out;
    std::string current;
    bool done = false;
    for (std::string l; std::getline(in, l);) {
        if (!l.empty() && l[0] == '[')
            current = l.substr(1, l.find(']') - 1);
        const std::string t = l.substr(0, l.find('='));
        if (!done && current == section && t.find_first_not_of(' ') != std::string::npos &&
            t.substr(0, t.find_last_not_of(' ') + 1) == key) {
            out << line << "\n";
            done = true;
            continue;
        }
        out << l << "\n";
    }
    if (done)
        return out.str();
    std::string added = out.str();
    const std::size_t header = added.find("[" + section + "]\n");
    EXPECT_NE(header, std::string::npos) << "no [" << section << "]";
    return added.insert(header + section.size() + 3, line + "\n");
}

/// Values a field must refuse, in file units.
std::vector<std::string> badValues(const config::Field& f) {
    switch (f.kind()) {
        case config::FieldKind::Flag:
            return {"maybe"};
        case config::FieldKind::Choice:
            return {"bogus"};
        case config::FieldKind::Text:
            return {""};
        default:
            break;
    }
    std::vector<std::string> v = {"abc", "nan", "1.5.2"};
    if (!f.range().contains(-1))
        v.push_back("-1");
    if (!f.range().contains(1e30))
        v.push_back("1e30");
    if (f.kind() == config::FieldKind::Integer)
        v.push_back("2.5");
    return v;
}

}  // namespace

TEST(IniSweep, EveryShippedIniFileWorksAsShipped) {
    test::TempDir dir;
    for (const IniUse& use : iniUses(dir))
        runWith(use, readFile(test::configIni(use.file)), true, dir);
}

TEST(IniSweep, GarbageIsAnErrorNamingTheFile) {
    test::TempDir dir;
    std::mt19937 rng(12);
    for (const IniUse& use : iniUses(dir)) {
        for (int trial = 0; trial < 3; ++trial) {
            std::string bytes(64 + trial * 500, '\0');
            for (char& c : bytes)
                c = static_cast<char>(rng() & 0xff);
            runWith(use, bytes, false, dir);
        }
        // Text that is no ini file, and the real file cut in the middle of a section header.
        runWith(use, "this is not an ini file\n", false, dir);
        const std::string text = readFile(test::configIni(use.file));
        runWith(use, text.substr(0, text.find("\n[") + 4) + "\n", false, dir);
    }
}

namespace {

/// The error of reading `iniText`'s [section] with a fresh struct, in process ("" when none).
std::string loadError(const std::string& iniText, const std::string& section,
                      const test::TempDir& dir) {
    const std::string path = dir.file("in-process.ini");
    std::ofstream(path, std::ios::binary) << iniText;
    return test::errorOf<config::ConfigError>([&] {
        test::sectionStructs().at(section)()->loadFromConfigFile(*config::openIniFile(path),
                                                                 section);
    });
}

/// A shipped file with one key of one [section] spoilt: a bad value or a letter dropped.
struct SpoiltKey {
    std::string section, key, text;
    std::string expected;  ///< what the error says ("[section] key = value: ...")
    bool throughApp;       ///< also run through the app: a sample, each run takes 0.2-1 s
};

/// Every key of every [section] of config_ini/`file` that is ours (see the file comment), with
/// each of its bad values and with a typo. The app runs a typo in the first key of each
/// section and one bad value of every 8th key (the first included), each kind in turn.
std::vector<SpoiltKey> spoiltKeys(const std::string& file) {
    const std::string path = test::configIni(file);
    const std::string text = readFile(path);
    std::vector<std::string> sections;
    config::openIniFile(path)->getAllSections(sections);
    std::vector<SpoiltKey> spoilt;
    for (const std::string& section : sections) {
        const auto it = test::sectionStructs().find(section);
        if (it == test::sectionStructs().end())
            continue;  // MRPT's (see the file comment)
        // The schema's fields read and write this struct: it must outlive them.
        const auto options = it->second();
        const config::OptionsSchema schema = options->schema();
        for (std::size_t i = 0; i < schema.fields().size(); ++i) {
            const config::Field& f = schema.fields()[i];
            const std::string key = f.key();
            const std::vector<std::string> bad = badValues(f);
            for (std::size_t v = 0; v < bad.size(); ++v) {
                spoilt.push_back({section, key, withLine(text, section, key, key + " = " + bad[v]),
                                  "[" + section + "] " + key + " = " + bad[v] + ": ",
                                  i % 8 == 0 && v == i / 8 % bad.size()});
            }
            const std::string typo = key.substr(0, 1) + key.substr(2);
            spoilt.push_back({section, key, withLine(text, section, key, typo + " = " + f.text()),
                              "[" + section + "] " + typo + " = " + f.text() +
                                  ": unknown key; did you mean '" + key + "'?",
                              i == 0});
        }
    }
    return spoilt;
}

const char* const kSpoiltFiles[] = {"features.ini", "graph-matcher.ini", "bench-matching-icp.ini",
                                    "toposlam-slam.ini", "sim-office.ini"};

}  // namespace

// In process: every key, every bad value.
TEST(IniKeys, MisspelledKeysAndBadValuesAreErrorsNamingTheKey) {
    test::TempDir dir;
    for (const char* file : kSpoiltFiles) {
        for (const SpoiltKey& k : spoiltKeys(file)) {
            EXPECT_NE(loadError(k.text, k.section, dir).find(k.expected), std::string::npos)
                << file << " [" << k.section << "] " << k.key << ": " << k.expected;
        }
    }
}

// Through the apps (the same code path): a sample of the keys above.
TEST(IniSweep, TheAppsNameTheMisspelledKeyOrBadValue) {
    test::TempDir dir;
    const std::vector<IniUse> uses = iniUses(dir);
    ASSERT_EQ(uses.size(), std::size(kSpoiltFiles));
    for (std::size_t u = 0; u < uses.size(); ++u) {
        ASSERT_EQ(uses[u].file, kSpoiltFiles[u]);
        for (const SpoiltKey& k : spoiltKeys(uses[u].file)) {
            if (!k.throughApp)
                continue;
            SCOPED_TRACE(uses[u].file + " [" + k.section + "] " + k.key);
            const std::string output = runWith(uses[u], k.text, false, dir, k.section);
            EXPECT_NE(output.find(k.expected), std::string::npos) << output;
        }
    }
}
