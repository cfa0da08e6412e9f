// The cloth textures (the woven default, the numbered debug patches) and image I/O.
#include "fabric_texture.h"
#include "image_io.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <fstream>
#include <gtest/gtest.h>
#include <set>

using namespace clothtear::app;

TEST(AppTexture, NumberedIsPatternedAndNumbered) {
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

namespace {

// Rec. 601 luminance of each pixel, in [0, 1].
std::vector<double> luminance(const Image& img) {
    std::vector<double> l(size_t(img.width) * img.height);
    for (size_t i = 0; i < l.size(); ++i)
        l[i] = (0.299 * img.rgba[i * 4] + 0.587 * img.rgba[i * 4 + 1] + 0.114 * img.rgba[i * 4 + 2]) / 255.0;
    return l;
}

// Mean absolute difference over the three channels between column a and column b (or rows, `rows`).
double lineDifference(const Image& img, int a, int b, bool rows) {
    double sum = 0;
    for (int k = 0; k < img.width; ++k) {
        const size_t pa = rows ? size_t(a) * img.width + k : size_t(k) * img.width + a;
        const size_t pb = rows ? size_t(b) * img.width + k : size_t(k) * img.width + b;
        for (int c = 0; c < 3; ++c) sum += std::abs(int(img.rgba[pa * 4 + c]) - int(img.rgba[pb * 4 + c]));
    }
    return sum / (3.0 * img.width);
}

// Mean absolute difference between the band of `width` columns from a and the one from b (or rows,
// `rows`), wrapping around the texture.
double bandDifference(const Image& img, int a, int b, int width, bool rows) {
    double sum = 0;
    for (int k = 0; k < width; ++k) sum += lineDifference(img, (a + k) % img.width, (b + k) % img.width, rows);
    return sum / width;
}

// The autocorrelation of the luminance along the rows (each row's mean removed, wrapping around since
// the texture tiles), averaged over all rows and divided by its value at lag 0.
std::vector<double> rowAutocorrelation(const Image& img, int maxLag) {
    const std::vector<double> l = luminance(img);
    const int n = img.width;
    std::vector<double> r(size_t(maxLag) + 1, 0.0), row(static_cast<size_t>(n));
    for (int y = 0; y < img.height; ++y) {
        double mean = 0;
        for (int x = 0; x < n; ++x) mean += l[size_t(y) * n + x];
        mean /= n;
        for (int x = 0; x < n; ++x) row[size_t(x)] = l[size_t(y) * n + x] - mean;
        for (int lag = 0; lag <= maxLag; ++lag)
            for (int x = 0; x < n; ++x) r[size_t(lag)] += row[size_t(x)] * row[size_t((x + lag) % n)];
    }
    for (int lag = maxLag; lag >= 0; --lag) r[size_t(lag)] /= r[0];
    return r;
}

const Image& woven() {
    static const Image img = makeWovenTexture(); // the default: 1024 px, kWovenThreads threads
    return img;
}

} // namespace

TEST(AppTexture, WovenTilesWithoutASeam) {
    const Image& img = woven();
    ASSERT_EQ(img.width, 1024);
    ASSERT_EQ(img.height, 1024);
    ASSERT_EQ(img.rgba.size(), 1024u * 1024u * 4u);
    const int n = img.width;
    for (const bool rows : {false, true}) {
        const char* what = rows ? "rows" : "columns";
        // Across the wrap (the last column next to the first; the last row next to the first) the colour
        // changes as much as across the thread boundaries inside that are at the same place in the weave:
        // between two colour stripes, at the same step of the 4-thread twill. And less than the largest
        // step inside.
        const double seam = lineDifference(img, n - 1, 0, rows);
        const int every = std::lcm(kWovenRepeat / 2, 4);
        double inside = 0, largest = 0;
        int boundaries = 0;
        for (int t = every; t < kWovenThreads; t += every, ++boundaries) {
            const int k = int(std::lround(double(t) * n / kWovenThreads));
            inside += lineDifference(img, k - 1, k, rows);
        }
        ASSERT_GT(boundaries, 0);
        inside /= boundaries;
        for (int k = 0; k + 1 < n; ++k) largest = std::max(largest, lineDifference(img, k, k + 1, rows));
        EXPECT_LE(seam, 1.25 * inside + 1.0) << what << ": " << seam << " across the wrap, " << inside << " inside";
        EXPECT_LE(seam, largest) << what << ": " << seam << " across the wrap, largest step inside " << largest;
        // The pattern goes on across the wrap: the band of one colour repeat centred on the wrap looks like
        // the one centred on the colour repeat boundary nearest the middle, the same place in the check (no
        // stripe cut short or doubled at the wrap), as much as two bands a repeat apart inside look alike.
        const double repeatPx = double(n) / kWovenThreads * kWovenRepeat;
        const int repeat = int(std::lround(repeatPx)), half = repeat / 2;
        const int middle = int(std::lround(std::round(n / 2 / repeatPx) * repeatPx));
        const double acrossWrap = bandDifference(img, n - half, middle - half, repeat, rows);
        const double apart = bandDifference(img, middle - half, middle - half + repeat, repeat, rows);
        EXPECT_LE(acrossWrap, 1.5 * apart + 1.0)
            << what << ": the band across the wrap differs by " << acrossWrap << ", bands inside by " << apart;
    }
}

TEST(AppTexture, WovenThreadsHaveTheDesignedPeriod) {
    const Image& img = woven();
    const double period = double(img.width) / kWovenThreads; // px a thread
    ASSERT_GT(period, 4.0) << "threads too thin to see";
    // The first peak of the autocorrelation along a row (past the central one) is the thread period:
    // every thread is shaded across its width and dark between two threads. Later peaks (two threads,
    // the 4-thread twill repeat, the colour check) come after it.
    const std::vector<double> r = rowAutocorrelation(img, 3 * int(period));
    int peak = 0;
    for (int lag = 2; lag < int(r.size()) - 1 && !peak; ++lag)
        if (r[size_t(lag)] > r[size_t(lag - 1)] && r[size_t(lag)] >= r[size_t(lag + 1)]) peak = lag;
    ASSERT_NE(peak, 0) << "no peak in the row autocorrelation up to 3 thread widths";
    EXPECT_NEAR(peak, period, 1.0);
    // A real peak, not a ripple of noise: a clear rise from the lowest point before it (the default
    // rises by about 0.11 of the variance; the strongest peak is the twill repeat at four threads).
    const double trough = *std::min_element(r.begin() + 1, r.begin() + peak);
    EXPECT_GT(r[size_t(peak)] - trough, 0.05) << "peak " << r[size_t(peak)] << ", trough " << trough;
}

TEST(AppTexture, WovenIsNeitherFlatNorNoise) {
    const Image& img = woven();
    const std::vector<double> l = luminance(img);
    double mean = 0, sq = 0, step = 0;
    for (double v : l) mean += v, sq += v * v;
    mean /= double(l.size());
    const double sd = std::sqrt(std::max(0.0, sq / double(l.size()) - mean * mean));
    // Not flat: threads and the check make the luminance vary...
    EXPECT_GT(sd, 0.04) << "mean " << mean;
    // ...within one colour square too (the top-left square is red warp over red weft).
    const int block = int(img.width / kWovenThreads * kWovenRepeat / 2);
    double bm = 0, bsq = 0;
    for (int y = 0; y < block; ++y)
        for (int x = 0; x < block; ++x) {
            const double v = l[size_t(y) * img.width + x];
            bm += v, bsq += v * v;
        }
    bm /= double(block * block);
    EXPECT_GT(std::sqrt(std::max(0.0, bsq / double(block * block) - bm * bm)), 0.03) << "threads not visible in one colour";
    // Not noise: neighbouring pixels are far closer than two random pixels (smooth threads).
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x + 1 < img.width; ++x)
            step += std::abs(l[size_t(y) * img.width + x + 1] - l[size_t(y) * img.width + x]);
    step /= double(img.height) * (img.width - 1);
    EXPECT_LT(step, 0.5 * sd) << "mean step between neighbours " << step << ", std dev " << sd;
    // Neither too dark nor washed out under the app's lighting.
    EXPECT_GT(mean, 0.1);
    EXPECT_LT(mean, 0.6);
}

TEST(AppTexture, WovenIsDeterministicAndRoundsThreadsToTheRepeat) {
    const Image a = makeWovenTexture(128, 16), b = makeWovenTexture(128, 16);
    EXPECT_EQ(a.rgba, b.rgba);
    EXPECT_EQ(makeWovenTexture(128, 20).rgba, a.rgba) << "20 threads round to 16 (one colour repeat)";
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
