// The default texture and image I/O.
#include "fabric_texture.h"
#include "image_io.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <set>

using namespace clothtear::app;

TEST(AppTexture, FabricIsPatternedAndNumbered) {
    const Image img = makeFabricTexture(256, 4);
    ASSERT_EQ(img.width, 256);
    ASSERT_EQ(img.rgba.size(), 256u * 256u * 4u);
    std::set<uint32_t> colours;
    for (size_t i = 0; i < img.rgba.size(); i += 4)
        colours.insert(uint32_t(img.rgba[i]) << 16 | uint32_t(img.rgba[i + 1]) << 8 | img.rgba[i + 2]);
    EXPECT_GT(colours.size(), 20u);
    // The patches differ: the centres of two neighbouring patches are different colours.
    auto at = [&](int x, int y) { return &img.rgba[(size_t(y) * 256 + x) * 4]; };
    EXPECT_NE(std::vector<uint8_t>(at(10, 10), at(10, 10) + 3), std::vector<uint8_t>(at(74, 10), at(74, 10) + 3));
}

TEST(AppTexture, PngRoundTripAndErrors) {
    const auto dir = std::filesystem::temp_directory_path() / "clothtear_app_texture_test";
    std::filesystem::create_directories(dir);
    const Image img = makeFabricTexture(64, 2);
    const std::string path = (dir / "f.png").string();
    ASSERT_EQ(savePng(path, img), "");
    auto back = loadImage(path);
    ASSERT_TRUE(back.ok()) << back.error;
    EXPECT_EQ(back.value.rgba, img.rgba);

    auto missing = loadImage((dir / "missing.png").string());
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error.find("missing.png"), std::string::npos);
    const std::string broken = (dir / "broken.png").string();
    std::ofstream(broken) << "this is not a png";
    auto bad = loadImage(broken);
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error.find("broken.png"), std::string::npos);
}
