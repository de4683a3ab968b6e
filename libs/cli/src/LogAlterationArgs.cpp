#include <toposlam/cli/LogAlterationArgs.h>

#include <utility>

namespace toposlam::cli {

namespace {
// "text" + " note" when there is a note.
std::string withNote(const std::string& text, const std::string& note, const std::string& tail) {
    return text + (note.empty() ? "" : " " + note) + tail;
}
}  // namespace

LogAlterationArgs::LogAlterationArgs(TCLAP::CmdLine& cmd, const Notes& notes)
    : keepEvery_("", "keep-every",
                 withNote("Keep one scan in N (the first, then every Nth): the log as a laser "
                          "with an N times lower scan rate would have recorded it; the odometry "
                          "is the pose at each kept scan.",
                          notes.keepEvery, " Default: 1 = every scan."),
                 1, NumberRange<std::size_t>::closed(1, 1000), "N", cmd),
      keepBeamEvery_("", "keep-beam-every",
                     withNote("Keep one beam in N of each scan (the first, then every Nth): the "
                              "log as a laser with N times the angle between beams would have "
                              "recorded it; each kept beam keeps its direction.",
                              notes.keepBeamEvery, " Default: 1 = every beam."),
                     1, NumberRange<std::size_t>::closed(1, 1000), "N", cmd),
      clipRange_("", "clip-range",
                 withNote("Readings at or beyond this range become invalid and the scans' "
                          "maximum range is at most this: the log as a laser that sees less far "
                          "would have recorded it.",
                          notes.clipRange, " Default: 0 = as recorded."),
                 0.0, NumberRange<double>::nonNegative(1000), "m", cmd),
      noOdometry_("", "no-odometry",
                  withNote("Leave the odometry out: the log as a robot without wheel odometry "
                           "would have recorded it (a laser-only log).",
                           notes.noOdometry, ""),
                  cmd),
      mirror_("", "mirror",
              withNote("The log's mirror image: every scan and the odometry with left and right "
                       "swapped, as the robot would have recorded them in the mirror image of its "
                       "building. Equally hard to map; a method that scores differently on it "
                       "depends on which way the robot turns.",
                       notes.mirror, ""),
              cmd) {}

io::LogAlteration LogAlterationArgs::alteration() const {
    io::LogAlteration a;
    a.keepEvery = keepEvery_.getValue();
    a.keepBeamEvery = keepBeamEvery_.getValue();
    a.clipRange = clipRange_.getValue();
    a.dropOdometry = noOdometry_.getValue();
    a.mirror = mirror_.getValue();
    return a;
}

std::vector<std::string> LogAlterationArgs::given() const {
    std::vector<std::string> names;
    const std::pair<bool, const char*> options[] = {{keepEvery_.isSet(), "--keep-every"},
                                                    {keepBeamEvery_.isSet(), "--keep-beam-every"},
                                                    {clipRange_.isSet(), "--clip-range"},
                                                    {noOdometry_.isSet(), "--no-odometry"},
                                                    {mirror_.isSet(), "--mirror"}};
    for (const auto& [set, name] : options) {
        if (set)
            names.emplace_back(name);
    }
    return names;
}

}  // namespace toposlam::cli
