// Cross-check of the B3 metric on the Kümmerle et al. benchmark logs: the raw odometry of each
// log, scored against its relations, must reproduce the odometry-only figures published with
// the data (../shared/data/SOURCES.md: intel 7.37 m / 39.2 deg, fr079 6.50 m / 30.3 deg,
// mit-csail 1.68 m / 5.1 deg). This checks the metric's convention, the relation parser and
// the stamp matching on real files at once: a wrong composition, a swapped relation or a
// missed stamp moves these means far beyond their rounding. The files are scored as published,
// their repeated lines included (countRepeatedRelations).
#include <gtest/gtest.h>
#include <toposlam/evaluation/LogOdometry.h>
#include <toposlam/evaluation/RelationFile.h>
#include <toposlam/evaluation/RelativePoseError.h>

#include <TestSupport.h>

using namespace toposlam::evaluation;

namespace {

struct Published {
    std::size_t relationCount;  ///< lines of the .relations file (SOURCES.md)
    std::size_t repeated;       ///< lines repeating an earlier one (`sort | uniq -d`)
    double translation;         ///< m, printed with 2 decimals
    double rotation;            ///< deg, printed with 1 decimal
};

void expectReproduces(const std::string& log, const std::string& relationsFile,
                      const Published& p) {
    const PoseRelations relations = loadRelations(relationsFile);
    EXPECT_EQ(countRepeatedRelations(relations), p.repeated);
    const RelativePoseErrorResult r = evaluateRelativePoseError(odometryAtScans(log), relations);
    EXPECT_EQ(r.totalRelations, p.relationCount);
    EXPECT_EQ(r.matchedRelations, p.relationCount) << "every relation stamp is a laser stamp";
    // Within the rounding of the published figures (half a unit of the last printed digit).
    EXPECT_NEAR(r.translation.mean, p.translation, 0.005);
    EXPECT_NEAR(r.rotation.mean, p.rotation, 0.05);
}

}  // namespace

TEST(SlamBenchmarkOdometry, IntelReproducesThePublishedFigures) {
    TOPOSLAM_SHARED_DATA_OR_SKIP(log, "slam/intel.clf");
    TOPOSLAM_SHARED_DATA_OR_SKIP(relations, "slam/intel.relations");
    expectReproduces(log, relations, {2984, 0, 7.37, 39.2});
}

TEST(SlamBenchmarkOdometry, Fr079ReproducesThePublishedFigures) {
    TOPOSLAM_SHARED_DATA_OR_SKIP(log, "slam/fr079.clf");
    TOPOSLAM_SHARED_DATA_OR_SKIP(relations, "slam/fr079.relations");
    expectReproduces(log, relations, {1685, 4, 6.50, 30.3});
}

TEST(SlamBenchmarkOdometry, MitCsailReproducesThePublishedFigures) {
    TOPOSLAM_SHARED_DATA_OR_SKIP(log, "slam/mit-csail.clf");
    TOPOSLAM_SHARED_DATA_OR_SKIP(relations, "slam/mit-csail.relations");
    expectReproduces(log, relations, {1172, 1, 1.68, 5.1});
}
