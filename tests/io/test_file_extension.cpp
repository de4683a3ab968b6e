#include <gtest/gtest.h>
#include <toposlam/io/FileExtension.h>
#include <toposlam/io/GridMapIO.h>

using toposlam::io::hasAnyExtension;
using toposlam::io::hasExtension;

TEST(FileExtension, CompoundExtensionsInAnyCase) {
    EXPECT_TRUE(hasExtension("out/map.gridmap.gz", ".gridmap.gz"));
    EXPECT_TRUE(hasExtension("out/map.gridmap.gz", ".gz"));
    EXPECT_TRUE(hasExtension("PLAN.PNG", ".png"));
    EXPECT_TRUE(hasExtension("log.Rawlog.GZ", ".rawlog.gz"));
    EXPECT_FALSE(hasExtension("map.gridmap.gz", ".gridmap"));
    EXPECT_FALSE(hasExtension("map.png.txt", ".png"));
    EXPECT_FALSE(hasExtension("mappng", ".png"));
}

TEST(FileExtension, ANameThatIsOnlyTheExtensionHasNone) {
    EXPECT_FALSE(hasExtension(".png", ".png"));
    EXPECT_FALSE(hasExtension("", ".png"));
    EXPECT_TRUE(hasExtension("a.png", ".png"));
}

TEST(FileExtension, AnyOfSeveral) {
    EXPECT_TRUE(hasAnyExtension("x.YML", {".yaml", ".yml"}));
    EXPECT_FALSE(hasAnyExtension("x.yaml.bak", {".yaml", ".yml"}));
    EXPECT_FALSE(hasAnyExtension("x.yaml", {}));
}

TEST(FileExtension, GridMapsAreToldFromLogsByName) {
    using toposlam::io::isGridMapPath;
    for (const char* map : {"a.gridmap", "a.GRIDMAP.GZ", "a.yaml", "a.yml", "a.png", "a.pgm",
                            "a.bmp", "a.jpg", "a.jpeg", "a.tif", "a.TIFF"})
        EXPECT_TRUE(isGridMapPath(map)) << map;
    for (const char* log : {"a.clf", "a.log.gz", "a.rawlog", "a.rawlog.gz", "a.gz", "png"})
        EXPECT_FALSE(isGridMapPath(log)) << log;
}
