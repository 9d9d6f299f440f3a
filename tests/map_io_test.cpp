/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// loadMap(): every format lands known pixels / cells / scans in the right cells with the right
// classes and world coordinates, real maps load with their measured sizes, and every file of
// the bad-input corpus is refused with a one-line InputError naming the file.

#include <gtest/gtest.h>
#include <mrpt/img/CImage.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/map_io.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "test_paths.h"

namespace fs = std::filesystem;
using mrpt::maps::COccupancyGridMap2D;
using mrpt_topoeval::InputError;
using mrpt_topoeval::LoadedMap;
using mrpt_topoeval::loadMap;
using mrpt_topoeval::MapLoadOptions;
using mrpt_topoeval::testing::makeTempDir;
using mrpt_topoeval::testing::sharedDataFile;
using mrpt_topoeval::testing::shareDir;
using mrpt_topoeval::testing::testsDir;

namespace
{
// ------------------------------------------------------------------ helpers

enum class Cls
{
    Occupied,
    Free,
    Unknown,
    Other
};

const char* name(Cls c)
{
    switch (c)
    {
        case Cls::Occupied:
            return "occupied";
        case Cls::Free:
            return "free";
        case Cls::Unknown:
            return "unknown";
        default:
            return "other";
    }
}

/** Cells hold quantised log-odds: compare with margins, never exact values. */
Cls classify(float p_free)
{
    if (p_free < 0.1f) return Cls::Occupied;
    if (p_free > 0.9f) return Cls::Free;
    if (std::abs(p_free - 0.5f) < 0.02f) return Cls::Unknown;
    return Cls::Other;
}

/** The cell that image pixel (col, row) must land in: image row 0 is the top (max y). */
float pixelCell(const COccupancyGridMap2D& g, int col, int row)
{
    return g.getCell(col, static_cast<int>(g.getSizeY()) - 1 - row);
}

void writeBytes(const std::string& path, const std::string& bytes)
{
    std::ofstream f(path, std::ios::binary);
    f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    ASSERT_TRUE(f.good()) << path;
}

/** Binary PGM; `pixels` row by row from the top, 8-bit (maxval < 256) or 16-bit big-endian. */
void writePgm(const std::string& path, int w, int h, const std::vector<int>& pixels,
              int maxval = 255)
{
    ASSERT_EQ(pixels.size(), static_cast<std::size_t>(w * h));
    std::string s = "P5\n# written by map_io_test\n" + std::to_string(w) + " " + std::to_string(h) +
                    "\n" + std::to_string(maxval) + "\n";
    for (const int v : pixels)
    {
        if (maxval > 255) s += static_cast<char>((v >> 8) & 0xFF);
        s += static_cast<char>(v & 0xFF);
    }
    writeBytes(path, s);
}

/** A ROS map YAML; `extra` lines are appended verbatim. */
void writeYaml(const std::string& path, const std::string& image, double res,
               const std::string& origin, const std::string& negate = "0",
               const std::string& extra = "")
{
    std::ostringstream s;
    s.precision(12);
    s << "image: " << image << "\nresolution: " << res << "\norigin: " << origin
      << "\nnegate: " << negate << "\noccupied_thresh: 0.65\nfree_thresh: 0.196\n"
      << extra;
    writeBytes(path, s.str());
}

/** Runs `f`, expects an InputError, checks it is one line starting with `file`, and returns
 * the message. Any other exception fails the test. */
std::string expectInputError(const std::function<void()>& f, const std::string& file)
{
    try
    {
        f();
    }
    catch (const InputError& e)
    {
        const std::string msg = e.what();
        EXPECT_EQ(msg.find('\n'), std::string::npos) << "not one line: " << msg;
        EXPECT_EQ(msg.rfind(file, 0), 0u) << "does not start with " << file << ": " << msg;
        return msg;
    }
    catch (const std::exception& e)
    {
        ADD_FAILURE() << "expected InputError, got another exception: " << e.what();
        return {};
    }
    ADD_FAILURE() << "expected InputError for " << file << ", nothing thrown";
    return {};
}

// The 4 x 3 test image used by the YAML tests, rows from the top. Grey 100 sits between the
// thresholds (p_occ = 0.608); 205 is ROS "unknown" (p_occ = 0.19608, just above 0.196).
const int kW = 4, kH = 3;
const std::vector<int> kPixels = {
    0,   254, 205, 100,  //
    254, 0,   254, 205,  //
    205, 254, 0,   254,
};

std::map<int, Cls> trinaryClasses()
{
    return {{0, Cls::Occupied}, {254, Cls::Free}, {205, Cls::Unknown}, {100, Cls::Unknown}};
}

void expectPixelClasses(const COccupancyGridMap2D& g, const std::map<int, Cls>& expected)
{
    ASSERT_EQ(g.getSizeX(), static_cast<unsigned>(kW));
    ASSERT_EQ(g.getSizeY(), static_cast<unsigned>(kH));
    for (int row = 0; row < kH; ++row)
        for (int col = 0; col < kW; ++col)
        {
            const int grey = kPixels[static_cast<std::size_t>(row * kW + col)];
            const float p = pixelCell(g, col, row);
            EXPECT_EQ(name(classify(p)), name(expected.at(grey)))
                << "pixel (" << col << ", " << row << ") grey " << grey << " P(free) " << p;
        }
}

// ------------------------------------------------------------------ ROS YAML

TEST(MapIoYaml, PixelsLandInTheRightCellsWithOriginAndTopRowAtMaxY)
{
    const std::string dir = makeTempDir("mapio_yaml");
    writePgm(dir + "/m.pgm", kW, kH, kPixels);
    writeYaml(dir + "/m.yaml", "m.pgm", 0.5, "[-1.0, 2.0, 0.0]");

    const LoadedMap m = loadMap(dir + "/m.yaml");
    EXPECT_EQ(m.format, "ros_yaml");
    EXPECT_EQ(m.file, dir + "/m.yaml");
    const COccupancyGridMap2D& g = m.grid;
    EXPECT_FALSE(g.isEmpty());
    EXPECT_FLOAT_EQ(g.getResolution(), 0.5f);
    EXPECT_FLOAT_EQ(g.getXMin(), -1.0f);
    EXPECT_FLOAT_EQ(g.getYMin(), 2.0f);
    EXPECT_FLOAT_EQ(g.getXMax(), 1.0f);
    EXPECT_FLOAT_EQ(g.getYMax(), 3.5f);
    expectPixelClasses(g, trinaryClasses());

    // World coordinates of pixel centres: top-left pixel (black) at (-0.75, 3.25), bottom-left
    // (205) at (-0.75, 2.25), bottom-right (254) at (0.75, 2.25).
    EXPECT_NEAR(g.idx2x(0), -0.75, 1e-6);
    EXPECT_NEAR(g.idx2y(kH - 1), 3.25, 1e-6);
    EXPECT_EQ(classify(g.getPos(-0.75f, 3.25f)), Cls::Occupied);
    EXPECT_EQ(classify(g.getPos(-0.75f, 2.25f)), Cls::Unknown);
    EXPECT_EQ(classify(g.getPos(0.75f, 2.25f)), Cls::Free);
    // The black diagonal runs from the top-left to bottom-right: (-0.25, 2.75) is pixel (1, 1).
    EXPECT_EQ(classify(g.getPos(-0.25f, 2.75f)), Cls::Occupied);
    EXPECT_EQ(classify(g.getPos(0.25f, 2.25f)), Cls::Occupied);
}

TEST(MapIoYaml, ScaleModeKeepsProbabilitiesBetweenThresholds)
{
    const std::string dir = makeTempDir("mapio_scale");
    writePgm(dir + "/m.pgm", kW, kH, kPixels);
    writeYaml(dir + "/m.yaml", "m.pgm", 0.5, "[0, 0, 0]", "0", "mode: scale\n");
    const COccupancyGridMap2D g = loadMap(dir + "/m.yaml").grid;
    EXPECT_EQ(classify(pixelCell(g, 0, 0)), Cls::Occupied);
    EXPECT_EQ(classify(pixelCell(g, 1, 0)), Cls::Free);
    // P(free) = 1 - p_occ: grey 100 -> 0.392, grey 205 -> 0.804 (ROS unknown grey is just
    // above free_thresh, so scale mode reads it as nearly free, as ROS map_server does).
    EXPECT_NEAR(pixelCell(g, 3, 0), 100.0 / 255.0, 0.02);
    EXPECT_NEAR(pixelCell(g, 2, 0), 205.0 / 255.0, 0.02);
}

TEST(MapIoYaml, NegateSwapsBlackAndWhite)
{
    const std::string dir = makeTempDir("mapio_negate");
    writePgm(dir + "/m.pgm", kW, kH, kPixels);
    for (const std::string negate : {"1", "true"})
    {
        writeYaml(dir + "/m.yaml", "m.pgm", 0.5, "[0, 0, 0]", negate);
        const COccupancyGridMap2D g = loadMap(dir + "/m.yaml").grid;
        // p_occ = grey / 255: 0 -> free, 254 and 205 (0.804) -> occupied, 100 (0.392) unknown.
        expectPixelClasses(
            g, {{0, Cls::Free}, {254, Cls::Occupied}, {205, Cls::Occupied}, {100, Cls::Unknown}});
    }
}

TEST(MapIoYaml, RawModeCopiesGreyAsOccupancy)
{
    const std::string dir = makeTempDir("mapio_raw");
    writePgm(dir + "/m.pgm", kW, kH, kPixels);
    writeYaml(dir + "/m.yaml", "m.pgm", 0.5, "[0, 0, 0]", "0", "mode: raw\n");
    const COccupancyGridMap2D g = loadMap(dir + "/m.yaml").grid;
    // ROS raw: the grey level is the occupancy value, so P(free) = 1 - grey / 255.
    EXPECT_EQ(classify(pixelCell(g, 0, 0)), Cls::Free);      // grey 0
    EXPECT_EQ(classify(pixelCell(g, 1, 0)), Cls::Occupied);  // grey 254
    EXPECT_NEAR(pixelCell(g, 2, 0), 1.0 - 205.0 / 255.0, 0.02);
    EXPECT_NEAR(pixelCell(g, 3, 0), 1.0 - 100.0 / 255.0, 0.02);
}

TEST(MapIoYaml, OriginOffTheCellGridKeepsExactSizeAndMovesLessThanHalfACell)
{
    const std::string dir = makeTempDir("mapio_snap");
    const int w = 7, h = 5;
    std::vector<int> px(w * h, 254);
    px[0] = 0;  // top-left pixel occupied
    writePgm(dir + "/m.pgm", w, h, px);
    const double origins[][2] = {{0.13, -0.27},   {-10.5, -6.7},      {0.025, 0.075},
                                 {-0.025, 0.125}, {1234.56, -987.65}, {-0.0249, 0.0251}};
    for (const double res : {0.05, 0.1, 0.011611161, 1.0})
        for (const auto& o : origins)
        {
            std::ostringstream origin;
            origin.precision(12);
            origin << "[" << o[0] << ", " << o[1] << ", 0.0]";
            writeYaml(dir + "/m.yaml", "m.pgm", res, origin.str());
            const COccupancyGridMap2D g = loadMap(dir + "/m.yaml").grid;
            SCOPED_TRACE("res " + std::to_string(res) + " origin " + origin.str());
            ASSERT_EQ(g.getSizeX(), static_cast<unsigned>(w));
            ASSERT_EQ(g.getSizeY(), static_cast<unsigned>(h));
            // Float coordinates far from zero: allow for float rounding on top of half a cell.
            const double tol = 0.5 * res + 1e-3;
            for (int c = 0; c < w; ++c)
                EXPECT_NEAR(g.idx2x(static_cast<size_t>(c)), o[0] + (c + 0.5) * res, tol);
            for (int r = 0; r < h; ++r)
                EXPECT_NEAR(g.idx2y(static_cast<size_t>(r)), o[1] + (r + 0.5) * res, tol);
            EXPECT_EQ(classify(g.getCell(0, h - 1)), Cls::Occupied);
            EXPECT_EQ(classify(g.getCell(1, h - 1)), Cls::Free);
        }
}

TEST(MapIoYaml, AcceptsYamlSyntaxVariants)
{
    const std::string dir = makeTempDir("mapio_syntax");
    writePgm(dir + "/my map.pgm", kW, kH, kPixels);
    // BOM, document marker, comments, CRLF line ends, a quoted file name with a space, a block
    // sequence for the origin, true/false for negate, upper-case mode, unknown keys ignored.
    const std::string text =
        "\xEF\xBB\xBF---\r\n"
        "# a ROS map\r\n"
        "image: \"my map.pgm\"  # quoted\r\n"
        "resolution: 5e-1\r\n"
        "origin:\r\n"
        "  - -1.0\r\n"
        "  - 2\r\n"
        "  - 0.0\r\n"
        "negate: false\r\n"
        "occupied_thresh: 0.65\r\n"
        "free_thresh: 0.196\r\n"
        "mode: Trinary\r\n"
        "'unused_key': [1, 'two', 3]\r\n";
    writeBytes(dir + "/m.yaml", text);
    const COccupancyGridMap2D g = loadMap(dir + "/m.yaml").grid;
    EXPECT_FLOAT_EQ(g.getXMin(), -1.0f);
    EXPECT_FLOAT_EQ(g.getYMin(), 2.0f);
    expectPixelClasses(g, trinaryClasses());

    // An absolute image path, and a YAML given with an upper-case extension.
    writeYaml(dir + "/ABS.YML", dir + "/my map.pgm", 0.5, "[0, 0, 0]");
    EXPECT_EQ(loadMap(dir + "/ABS.YML").grid.getSizeX(), static_cast<unsigned>(kW));
}

TEST(MapIoYaml, YawIsRefusedUnlessNegligible)
{
    const std::string dir = makeTempDir("mapio_yaw");
    writePgm(dir + "/m.pgm", kW, kH, kPixels);
    writeYaml(dir + "/m.yaml", "m.pgm", 0.5, "[0, 0, 1e-12]");
    EXPECT_NO_THROW(loadMap(dir + "/m.yaml"));
    writeYaml(dir + "/m.yaml", "m.pgm", 0.5, "[0, 0, 0.1]");
    const std::string msg = expectInputError([&] { loadMap(dir + "/m.yaml"); }, dir + "/m.yaml");
    EXPECT_NE(msg.find("yaw"), std::string::npos) << msg;
}

TEST(MapIoYaml, MessagesNameFileKeyAndValue)
{
    const std::string dir = makeTempDir("mapio_msg");
    writePgm(dir + "/m.pgm", kW, kH, kPixels);
    writeYaml(dir + "/map.yaml", "m.pgm", -1, "[0, 0, 0]");
    EXPECT_EQ(
        expectInputError([&] { loadMap(dir + "/map.yaml"); }, dir + "/map.yaml"),
        dir + "/map.yaml: key 'resolution' = -1 must be a positive number of metres per cell");
}

// ------------------------------------------------------------------ plain images

TEST(MapIoImage, PlainPngUsesDefaultResolutionAndLowerLeftOrigin)
{
    const std::string dir = makeTempDir("mapio_png");
    mrpt::img::CImage img(5, 4, mrpt::img::CH_GRAY);
    img.filledRectangle(0, 0, 4, 3, mrpt::img::TColor(254, 254, 254));
    img.setPixel(0, 0, 0);    // top-left: occupied
    img.setPixel(4, 3, 205);  // bottom-right: unknown
    ASSERT_TRUE(img.saveToFile(dir + "/plain.png"));

    const LoadedMap m = loadMap(dir + "/plain.png");
    EXPECT_EQ(m.format, "image");
    const COccupancyGridMap2D& g = m.grid;
    EXPECT_FALSE(g.isEmpty());
    ASSERT_EQ(g.getSizeX(), 5u);
    ASSERT_EQ(g.getSizeY(), 4u);
    EXPECT_FLOAT_EQ(g.getResolution(), 0.05f);
    EXPECT_FLOAT_EQ(g.getXMin(), 0.0f);
    EXPECT_FLOAT_EQ(g.getYMin(), 0.0f);
    EXPECT_EQ(classify(g.getCell(0, 3)), Cls::Occupied);
    EXPECT_EQ(classify(g.getPos(0.025f, 0.175f)), Cls::Occupied);  // top-left pixel centre
    EXPECT_EQ(classify(g.getCell(4, 0)), Cls::Unknown);
    int free_cells = 0;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 5; ++x) free_cells += classify(g.getCell(x, y)) == Cls::Free;
    EXPECT_EQ(free_cells, 18);

    MapLoadOptions opts;
    opts.resolution_m = 0.2;
    const COccupancyGridMap2D g2 = loadMap(dir + "/plain.png", opts).grid;
    EXPECT_FLOAT_EQ(g2.getResolution(), 0.2f);
    EXPECT_FLOAT_EQ(g2.getXMax(), 1.0f);
}

TEST(MapIoImage, ThresholdOptionsApplyToPlainImages)
{
    const std::string dir = makeTempDir("mapio_thresh");
    writePgm(dir + "/m.pgm", kW, kH, kPixels);
    MapLoadOptions opts;
    opts.occupied_thresh = 0.5;  // grey 100 (p_occ 0.608) becomes occupied
    opts.free_thresh = 0.25;     // grey 205 (p_occ 0.196) becomes free
    const COccupancyGridMap2D g = loadMap(dir + "/m.pgm", opts).grid;
    expectPixelClasses(
        g, {{0, Cls::Occupied}, {254, Cls::Free}, {205, Cls::Free}, {100, Cls::Occupied}});

    opts.free_thresh = 0.7;
    const std::string msg =
        expectInputError([&] { loadMap(dir + "/m.pgm", opts); }, dir + "/m.pgm");
    EXPECT_NE(msg.find("free_thresh"), std::string::npos) << msg;
    opts = MapLoadOptions{};
    opts.resolution_m = 0;
    EXPECT_NE(expectInputError([&] { loadMap(dir + "/m.pgm", opts); }, dir + "/m.pgm")
                  .find("resolution_m"),
              std::string::npos);
}

TEST(MapIoImage, ColourImagesAverageTheirChannels)
{
    const std::string dir = makeTempDir("mapio_colour");
    mrpt::img::CImage img(3, 1, mrpt::img::CH_RGB);
    img.setPixel(0, 0, 0xFFFF00);  // yellow: mean 170 -> p_occ 0.333 -> unknown
    img.setPixel(1, 0, 0xFF0000);  // red: mean 85 -> p_occ 0.667 -> occupied
    img.setPixel(2, 0, 0xFFFFFF);  // white: free
    ASSERT_TRUE(img.saveToFile(dir + "/c.png"));
    const COccupancyGridMap2D g = loadMap(dir + "/c.png").grid;
    // A luminance conversion would make yellow free (226) and red occupied: averaging, as ROS
    // map_server does, makes yellow unknown.
    EXPECT_EQ(classify(g.getCell(0, 0)), Cls::Unknown);
    EXPECT_EQ(classify(g.getCell(1, 0)), Cls::Occupied);
    EXPECT_EQ(classify(g.getCell(2, 0)), Cls::Free);
}

TEST(MapIoImage, NetpbmSamplesAreScaledByTheirMaxval)
{
    const std::string dir = makeTempDir("mapio_maxval");
    // 16-bit: 0 black, 65535 white, 205 * 257 the ROS unknown grey.
    writePgm(dir + "/w16.pgm", 3, 1, {0, 65535, 205 * 257}, 65535);
    COccupancyGridMap2D g = loadMap(dir + "/w16.pgm").grid;
    EXPECT_EQ(classify(g.getCell(0, 0)), Cls::Occupied);
    EXPECT_EQ(classify(g.getCell(1, 0)), Cls::Free);
    EXPECT_EQ(classify(g.getCell(2, 0)), Cls::Unknown);
    // maxval 100: 100 is white (read as 100/255 it would be unknown), 50 is mid-grey.
    writePgm(dir + "/m100.pgm", 3, 1, {0, 100, 50}, 100);
    g = loadMap(dir + "/m100.pgm").grid;
    EXPECT_EQ(classify(g.getCell(0, 0)), Cls::Occupied);
    EXPECT_EQ(classify(g.getCell(1, 0)), Cls::Free);
    EXPECT_EQ(classify(g.getCell(2, 0)), Cls::Unknown);
    // Plain (ASCII) PGM.
    writeBytes(dir + "/ascii.pgm", "P2\n# c\n3 1\n255\n0 254 205\n");
    g = loadMap(dir + "/ascii.pgm").grid;
    EXPECT_EQ(classify(g.getCell(0, 0)), Cls::Occupied);
    EXPECT_EQ(classify(g.getCell(1, 0)), Cls::Free);
    EXPECT_EQ(classify(g.getCell(2, 0)), Cls::Unknown);
}

TEST(MapIoImage, BmpAndJpegLoad)
{
    const std::string dir = makeTempDir("mapio_bmpjpg");
    // Left half black, right half white; JPEG blurs the edge, so test away from it.
    mrpt::img::CImage img(16, 8, mrpt::img::CH_GRAY);
    img.filledRectangle(0, 0, 15, 7, mrpt::img::TColor(255, 255, 255));
    img.filledRectangle(0, 0, 7, 7, mrpt::img::TColor(0, 0, 0));
    for (const std::string ext : {".bmp", ".jpg", ".JPEG"})
    {
        SCOPED_TRACE(ext);
        ASSERT_TRUE(img.saveToFile(dir + "/half" + ext));
        const COccupancyGridMap2D g = loadMap(dir + "/half" + ext).grid;
        ASSERT_EQ(g.getSizeX(), 16u);
        ASSERT_EQ(g.getSizeY(), 8u);
        EXPECT_EQ(classify(g.getCell(2, 4)), Cls::Occupied);
        EXPECT_EQ(classify(g.getCell(13, 4)), Cls::Free);
    }
}

// ------------------------------------------------------------------ MRPT serialized files

TEST(MapIoGridmap, RoundTripGzAndPlain)
{
    const std::string dir = makeTempDir("mapio_gridmap");
    COccupancyGridMap2D grid;
    grid.setSize(-2.3f, 4.1f, 1.0f, 3.0f, 0.1f, 0.5f);
    for (int i = 0; i < 20; ++i)
    {
        grid.setCell(i, i % 20, 0.0f);
        grid.setCell(i + 30, 5, 1.0f);
        grid.setCell(i + 5, 15, 0.3f);
    }
    {
        mrpt::io::CFileGZOutputStream f(dir + "/g.gridmap.gz");
        mrpt::serialization::archiveFrom(f) << grid;
    }
    {
        mrpt::io::CFileOutputStream f(dir + "/g.gridmap");
        mrpt::serialization::archiveFrom(f) << grid;
    }
    for (const std::string file : {"/g.gridmap.gz", "/g.gridmap"})
    {
        SCOPED_TRACE(file);
        const LoadedMap m = loadMap(dir + file);
        EXPECT_EQ(m.format, "gridmap");
        EXPECT_EQ(m.grid.getSizeX(), grid.getSizeX());
        EXPECT_EQ(m.grid.getSizeY(), grid.getSizeY());
        EXPECT_FLOAT_EQ(m.grid.getXMin(), grid.getXMin());
        EXPECT_FLOAT_EQ(m.grid.getYMin(), grid.getYMin());
        EXPECT_FLOAT_EQ(m.grid.getResolution(), grid.getResolution());
        EXPECT_TRUE(m.grid.getRawMap() == grid.getRawMap()) << "cells differ";
    }

    MapLoadOptions small;
    small.max_cells = 100;
    const std::string msg =
        expectInputError([&] { loadMap(dir + "/g.gridmap.gz", small); }, dir + "/g.gridmap.gz");
    EXPECT_NE(msg.find("max_cells"), std::string::npos) << msg;
}

/** One keyframe at `pose` with a 180-degree scan of `n` rays, all `range` metres. */
mrpt::maps::CSimpleMap oneScanMap(const mrpt::poses::CPose3D& pose, float range, size_t n = 181)
{
    auto scan = std::make_shared<mrpt::obs::CObservation2DRangeScan>();
    scan->aperture = static_cast<float>(M_PI);
    scan->maxRange = 10.0f;
    scan->resizeScan(n);
    for (size_t i = 0; i < n; ++i)
    {
        scan->setScanRange(i, range);
        scan->setScanRangeValidity(i, true);
    }
    auto sf = std::make_shared<mrpt::obs::CSensoryFrame>();
    sf->insert(scan);
    mrpt::maps::CSimpleMap sm;
    sm.insert(std::make_shared<mrpt::poses::CPose3DPDFGaussian>(pose), sf);
    return sm;
}

TEST(MapIoSimplemap, RendersScansWhereTheyHit)
{
    const std::string dir = makeTempDir("mapio_simplemap");
    // Robot at (1, 2) facing +x: the scan's arc of radius 3 m spans angles -90..+90 degrees.
    const mrpt::maps::CSimpleMap sm = oneScanMap(mrpt::poses::CPose3D(1, 2, 0, 0, 0, 0), 3.0f);
    {
        mrpt::io::CFileGZOutputStream f(dir + "/one.simplemap");
        mrpt::serialization::archiveFrom(f) << sm;
    }
    const LoadedMap m = loadMap(dir + "/one.simplemap");
    EXPECT_EQ(m.format, "simplemap");
    const COccupancyGridMap2D& g = m.grid;
    EXPECT_FLOAT_EQ(g.getResolution(), 0.05f);

    const auto minAround = [&](double x, double y)
    {
        float p = 1.0f;
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                p = std::min(p, g.getPos(static_cast<float>(x + 0.05 * dx),
                                         static_cast<float>(y + 0.05 * dy)));
        return p;
    };
    // Hits straight ahead, 45 degrees left and straight right are occupied.
    EXPECT_LT(minAround(4.0, 2.0), 0.4f);
    EXPECT_LT(minAround(1 + 3 * std::cos(M_PI / 4), 2 + 3 * std::sin(M_PI / 4)), 0.4f);
    EXPECT_LT(minAround(1.0, -1.0), 0.4f);
    // Inside the arc is free, behind the wall and behind the robot unknown.
    EXPECT_GT(g.getPos(2.5f, 2.0f), 0.6f);
    EXPECT_GT(g.getPos(1.0f, 3.5f), 0.6f);
    EXPECT_NEAR(g.getPos(5.5f, 2.0f), 0.5f, 0.02f);
    EXPECT_NEAR(g.getPos(-1.0f, 2.0f), 0.5f, 0.02f);
    // The arc is 3 pi m long: about 190 cells at 0.05 m.
    int occupied = 0;
    for (unsigned y = 0; y < g.getSizeY(); ++y)
        for (unsigned x = 0; x < g.getSizeX(); ++x) occupied += g.getCell(x, y) < 0.4f;
    EXPECT_GT(occupied, 120);
    EXPECT_LT(occupied, 600);

    MapLoadOptions opts;
    opts.resolution_m = 0.1;
    EXPECT_FLOAT_EQ(loadMap(dir + "/one.simplemap", opts).grid.getResolution(), 0.1f);
    opts.max_cells = 1000;
    const std::string msg =
        expectInputError([&] { loadMap(dir + "/one.simplemap", opts); }, dir + "/one.simplemap");
    EXPECT_NE(msg.find("max_cells"), std::string::npos) << msg;
}

// ------------------------------------------------------------------ bad input

TEST(MapIoErrors, FileProblemsGetClearMessages)
{
    const std::string dir = makeTempDir("mapio_errors");
    EXPECT_NE(expectInputError([&] { loadMap(dir + "/nothing.yaml"); }, dir + "/nothing.yaml")
                  .find("no such file"),
              std::string::npos);
    fs::create_directory(dir + "/folder.yaml");
    EXPECT_NE(expectInputError([&] { loadMap(dir + "/folder.yaml"); }, dir + "/folder.yaml")
                  .find("directory"),
              std::string::npos);
    writeBytes(dir + "/map.tiff", "II*");
    const std::string msg =
        expectInputError([&] { loadMap(dir + "/map.tiff"); }, dir + "/map.tiff");
    EXPECT_NE(msg.find(".simplemap.gz"), std::string::npos) << "lists the formats: " << msg;
    EXPECT_THROW(loadMap(""), InputError);

    // Permissions do not stop root: only meaningful for other users.
    if (::geteuid() != 0)
    {
        writePgm(dir + "/locked.pgm", kW, kH, kPixels);
        fs::permissions(dir + "/locked.pgm", fs::perms::none);
        EXPECT_NE(expectInputError([&] { loadMap(dir + "/locked.pgm"); }, dir + "/locked.pgm")
                      .find("cannot be read"),
                  std::string::npos);
    }

    // An image over max_cells is refused from its header.
    writePgm(dir + "/m.pgm", kW, kH, kPixels);
    MapLoadOptions opts;
    opts.max_cells = 11;
    EXPECT_NE(
        expectInputError([&] { loadMap(dir + "/m.pgm", opts); }, dir + "/m.pgm").find("max_cells"),
        std::string::npos);
}

/** Every file of tests/data/bad_inputs, what it is, and a word its message must contain. */
const std::map<std::string, std::string> kBadInputs = {
    {"absurd_limits.gridmap", "max_cells"},  // limits for 1e6 x 1e6 cells
    {"binary.yaml", "not a text file"},      // random bytes
    {"duplicate_key.yaml", "twice"},         // resolution given twice
    {"empty.gridmap", "empty"},
    {"empty.png", "empty"},
    {"empty.simplemap", "empty"},
    {"empty.yaml", "empty"},
    {"far_apart_keyframes.simplemap", "max_cells"},                  // keyframes 2000 km apart
    {"frame_count_corrupt.simplemap", "a sensory frame declares"},   // 2^31-1 observations
    {"grid_instead_of_keyframes.simplemap", "COccupancyGridMap2D"},  // wrong class
    {"huge_dims.jpg", "max_cells"},                                  // SOF declares 65000 x 65000
    {"huge_dims.pgm", "max_cells"},                                  // 200000 x 200000
    {"huge_dims.png", "max_cells"},                                  // IHDR 100000 x 100000
    {"image_huge.yaml", "max_cells"},                                // names huge_dims.pgm
    {"image_not_an_image.yaml", "not a PNG"},                        // names not_an_image.png
    {"image_not_found.yaml", "no such file"},                        // names does_not_exist.pgm
    {"image_truncated.yaml", "cannot decode"},                       // names truncated.png
    {"infinite_range.simplemap", "non-finite range"},                // a valid range of -inf
    {"keyframe_count_corrupt.simplemap", "keyframe list declares"},  // 335544326 keyframes
    {"map.txt", "unknown map format"},
    {"maxval_zero.pgm", "maxval"},
    {"missing_image_key.yaml", "'image'"},
    {"missing_resolution.yaml", "'resolution'"},
    {"mode_unknown.yaml", "'mode'"},        // mode: fancy
    {"negate_two.yaml", "'negate'"},        // negate: 2
    {"nested_mapping.yaml", "line 4"},      // origin as a mapping
    {"no_scan_data.jpg", "cannot decode"},  // frame header, no scan
    {"not_an_image.png", "not a PNG"},      // text
    {"occupied_thresh_above_one.yaml", "'occupied_thresh' = 1.5"},
    {"origin_inf.yaml", "'origin'"},             // [.inf, 2, 0]
    {"origin_two_values.yaml", "'origin'"},      // [1, 2]
    {"origin_yaw.yaml", "yaw"},                  // [1, 2, 0.5]
    {"points_map.gridmap", "CSimplePointsMap"},  // wrong class
    {"random_bytes.gridmap", "not an MRPT serialized file"},
    {"ray_count_corrupt.simplemap", "a laser scan declares"},  // 3.3e9 rays (crashed MRPT)
    {"resolution_nan.yaml", "'resolution' = .nan"},
    {"resolution_negative.yaml", "'resolution' = -1"},
    {"resolution_text.yaml", "'resolution' = abc"},
    {"resolution_zero.yaml", "'resolution' = 0"},
    {"thresholds_swapped.yaml", "'free_thresh'"},  // free 0.65, occupied 0.196
    {"truncated.gridmap.gz", "truncated"},         // half of a gz grid
    {"truncated.png", "cannot decode"},            // cut in IDAT
    {"truncated.simplemap.gz", "truncated"},       // half of a gz simple map
    {"truncated_header.bmp", "truncated BMP header"},
    {"truncated_header.png", "truncated PNG header"},
    {"truncated_in_ray_count.simplemap", "truncated"},  // cut inside a uint32 ray count
    {"truncated_pixels.pgm", "cannot decode"},          // 3 of 16 pixel bytes
    {"truncated_plain.gridmap", "truncated"},           // uncompressed grid cut in its cells
    {"unclosed_list.yaml", "line 3"},                   // origin: [0.0, 0.0, 0.0
    {"zero_width.png", "0 x 10"},                       // IHDR width 0
};

TEST(MapIoErrors, EveryBadInputIsRefusedWithItsFileName)
{
    const fs::path dir = fs::path(testsDir()) / "data" / "bad_inputs";
    ASSERT_TRUE(fs::is_directory(dir)) << dir;
    std::set<std::string> seen;
    for (const auto& entry : fs::directory_iterator(dir))
    {
        if (!entry.is_regular_file()) continue;  // support/ holds valid helpers
        const std::string file = entry.path().filename().string();
        const std::string path = entry.path().string();
        SCOPED_TRACE(file);
        seen.insert(file);
        const auto it = kBadInputs.find(file);
        EXPECT_NE(it, kBadInputs.end())
            << "add " << file << " and its expected message to kBadInputs";
        const std::string msg = expectInputError([&] { loadMap(path); }, path);
        EXPECT_NE(msg.find(file), std::string::npos) << msg;
        if (it != kBadInputs.end())
        {
            EXPECT_NE(msg.find(it->second), std::string::npos)
                << "expected '" << it->second << "' in: " << msg;
        }
    }
    for (const auto& [file, word] : kBadInputs)
        EXPECT_TRUE(seen.count(file)) << file << " is listed but missing from " << dir;
}

// ------------------------------------------------------------------ real maps

struct RealMap
{
    std::string file;
    unsigned w, h;
    float x_min, y_min;
    // Cell classes counted independently from the image pixels with the YAML thresholds
    // (-1: not checked).
    int occupied, free_cells;
};

void expectRealMap(const std::string& path, const RealMap& r)
{
    SCOPED_TRACE(path);
    const COccupancyGridMap2D g = loadMap(path).grid;
    EXPECT_EQ(g.getSizeX(), r.w);
    EXPECT_EQ(g.getSizeY(), r.h);
    EXPECT_NEAR(g.getXMin(), r.x_min, 1e-3);
    EXPECT_NEAR(g.getYMin(), r.y_min, 1e-3);
    EXPECT_FLOAT_EQ(g.getResolution(), 0.05f);
    if (r.occupied < 0) return;
    int occ = 0, free_cells = 0, other = 0;
    for (unsigned y = 0; y < g.getSizeY(); ++y)
        for (unsigned x = 0; x < g.getSizeX(); ++x)
        {
            const Cls c = classify(g.getCell(x, y));
            occ += c == Cls::Occupied;
            free_cells += c == Cls::Free;
            other += c == Cls::Other;
        }
    EXPECT_EQ(occ, r.occupied);
    EXPECT_EQ(free_cells, r.free_cells);
    EXPECT_EQ(other, 0);  // trinary YAMLs give only three classes
}

const RealMap kHouseGt{"house_gt_trinary_res0.05.yaml", 420, 269, -10.5f, -6.7f, 2805, 69643};
const RealMap kHouse6cc{"map_6ccdcaa.yaml", 500, 500, -12.5f, -12.5f, 3442, 63021};
const RealMap kHouse233{"map_2333d24.yaml", 608, 384, -10.0f, -10.0f, 3782, 62063};

TEST(MapIoRealData, SharedMapsLoadWithMeasuredSizes)
{
    bool any = false;
    for (const RealMap& r : {kHouseGt, kHouse6cc, kHouse233})
        if (const auto p = sharedDataFile("house/" + r.file))
        {
            expectRealMap(*p, r);
            any = true;
        }
    if (const auto p = sharedDataFile("radish/intel-corrected_ref.yaml"))
    {
        expectRealMap(*p, {"", 1000, 820, -26.0f, -26.0f, 13099, 167707});
        any = true;
    }
    if (const auto p = sharedDataFile("slam_maps/intel_icp-slam_keyframes-o2m.gridmap"))
    {
        // An MRPT serialized grid (gzip-compressed despite the plain extension).
        expectRealMap(*p, {"", 1020, 1220, -28.0f, -37.0f, -1, -1});
        any = true;
    }
    if (const auto p = sharedDataFile("slam_maps/intel_icp-slam.simplemap"))
    {
        const LoadedMap m = loadMap(*p);
        EXPECT_EQ(m.format, "simplemap");
        // Rendered with MRPT's default insertion options (the .gridmap above was made by
        // icp-slam with its own, hence the different extent).
        EXPECT_EQ(m.grid.getSizeX(), 860u);
        EXPECT_EQ(m.grid.getSizeY(), 1160u);
        EXPECT_NEAR(m.grid.getXMin(), -22.0, 1e-3);
        EXPECT_NEAR(m.grid.getYMin(), -37.0, 1e-3);
        any = true;
    }
    if (!any) GTEST_SKIP() << "../shared/data is not available";
}

TEST(MapIoRealData, ShareCopiesLoad)
{
    const std::string maps = shareDir() + "/maps/";
    for (const RealMap& r : {kHouseGt, kHouse6cc, kHouse233}) expectRealMap(maps + r.file, r);

    // In the ground truth image, the first occupied pixel in reading order (measured with an
    // independent PNG decoder) is column 189 of row 19: world (-10.5 + 189.5 * 0.05,
    // -6.7 + (269 - 19 - 0.5) * 0.05) = (-1.025, 5.775).
    const COccupancyGridMap2D g = loadMap(maps + kHouseGt.file).grid;
    EXPECT_EQ(classify(g.getPos(-1.025f, 5.775f)), Cls::Occupied);
    for (int row = 0; row <= 19; ++row)
        for (int col = 0; col < (row < 19 ? 420 : 189); ++col)
            ASSERT_NE(classify(pixelCell(g, col, row)), Cls::Occupied) << col << ", " << row;
    EXPECT_EQ(classify(pixelCell(g, 189, 19)), Cls::Occupied);
}

}  // namespace
