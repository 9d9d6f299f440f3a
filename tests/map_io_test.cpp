/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// loadMap(): every format lands known pixels / cells / scans in the right cells with the right
// classes and world coordinates, real maps load with their measured sizes, and every file of
// the bad-input corpus is refused with a one-line InputError naming the file.

#include <gtest/gtest.h>
#include <mrpt/img/CImage.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>
#include <mrpt/poses/CPosePDFParticles.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/maps/load_map.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "../libmrpt_topoeval/src/maps/serialized_layout.h"  // header-only, internal
#include "test_paths.h"

namespace fs = std::filesystem;
using mrpt::maps::COccupancyGridMap2D;
using mrpt_topoeval::InputError;
using mrpt_topoeval::LoadedMap;
using mrpt_topoeval::loadMap;
using mrpt_topoeval::MapLoadOptions;
using mrpt_topoeval::testing::ScopedTempDir;
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
    const ScopedTempDir tmp("mapio_yaml");
    const std::string& dir = tmp.path;
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
    const ScopedTempDir tmp("mapio_scale");
    const std::string& dir = tmp.path;
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
    const ScopedTempDir tmp("mapio_negate");
    const std::string& dir = tmp.path;
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
    const ScopedTempDir tmp("mapio_raw");
    const std::string& dir = tmp.path;
    writePgm(dir + "/m.pgm", kW, kH, kPixels);
    writeYaml(dir + "/m.yaml", "m.pgm", 0.5, "[0, 0, 0]", "0", "mode: raw\n");
    const COccupancyGridMap2D g = loadMap(dir + "/m.yaml").grid;
    // ROS raw: the grey level is the occupancy value, so P(free) = 1 - grey / 255.
    EXPECT_EQ(classify(pixelCell(g, 0, 0)), Cls::Free);      // grey 0
    EXPECT_EQ(classify(pixelCell(g, 1, 0)), Cls::Occupied);  // grey 254
    EXPECT_NEAR(pixelCell(g, 2, 0), 1.0 - 205.0 / 255.0, 0.02);
    EXPECT_NEAR(pixelCell(g, 3, 0), 1.0 - 100.0 / 255.0, 0.02);
}

// nav2 Humble's map_saver wrote `free_thresh: 0.25` beside images whose unknown cells are grey
// 205 (p_occ 0.196): read literally, every unknown cell, the whole outside of the building, is
// free (navigation2 PR #5278 fixed the saver). In an image of map_saver's greys only, 205 stays
// unknown, with a note; with another grey in the image, or the option off, the thresholds decide.
TEST(MapIoYaml, MapSaverUnknownGreyStaysUnknownUnderAHighFreeThreshold)
{
    const ScopedTempDir tmp("mapio_saver_unknown");
    const std::string& dir = tmp.path;
    const std::vector<int> saver = {0, 254, 205, 255, 254, 0, 254, 205, 205, 254, 0, 254};
    std::vector<int> other = saver;
    other[3] = 100;  // a grey map_saver never writes
    writePgm(dir + "/saver.pgm", kW, kH, saver);
    writePgm(dir + "/other.pgm", kW, kH, other);
    auto yaml =
        [&](const std::string& image, const std::string& free_thresh, const std::string& mode)
    {
        const std::string path = dir + "/m.yaml";
        writeBytes(path, "image: " + image +
                             "\nresolution: 0.5\norigin: [0, 0, 0]\nnegate: 0\n"
                             "occupied_thresh: 0.65\nfree_thresh: " +
                             free_thresh + "\n" + mode);
        return path;
    };
    MapLoadOptions off;
    off.trinary_unknown_grey = -1;
    for (const std::string mode : {"", "mode: trinary\n"})
    {
        const LoadedMap m = loadMap(yaml("saver.pgm", "0.25", mode));
        EXPECT_EQ(classify(pixelCell(m.grid, 2, 0)), Cls::Unknown) << mode;
        EXPECT_EQ(classify(pixelCell(m.grid, 1, 0)), Cls::Free);
        EXPECT_EQ(classify(pixelCell(m.grid, 3, 0)), Cls::Free);  // 255
        EXPECT_EQ(classify(pixelCell(m.grid, 0, 0)), Cls::Occupied);
        ASSERT_EQ(m.notes.size(), 1u);
        EXPECT_NE(m.notes[0].find("free_thresh 0.25"), std::string::npos) << m.notes[0];
        EXPECT_NE(m.notes[0].find("trinary_unknown_grey"), std::string::npos) << m.notes[0];

        const LoadedMap literal = loadMap(yaml("saver.pgm", "0.25", mode), off);
        EXPECT_EQ(classify(pixelCell(literal.grid, 2, 0)), Cls::Free);
        EXPECT_TRUE(literal.notes.empty());

        // Another grey: not map_saver's image; 205 stays free, and a note says why.
        const LoadedMap drawn = loadMap(yaml("other.pgm", "0.25", mode));
        EXPECT_EQ(classify(pixelCell(drawn.grid, 2, 0)), Cls::Free);
        ASSERT_EQ(drawn.notes.size(), 1u);
        EXPECT_NE(drawn.notes[0].find("read as free"), std::string::npos) << drawn.notes[0];
    }
    // ROS's own default already reads 205 as unknown: nothing to note.
    const LoadedMap standard = loadMap(yaml("saver.pgm", "0.196", ""));
    EXPECT_EQ(classify(pixelCell(standard.grid, 2, 0)), Cls::Unknown);
    EXPECT_TRUE(standard.notes.empty());
    // Scale mode keeps every grey's probability, as map_server does.
    const LoadedMap scale = loadMap(yaml("saver.pgm", "0.25", "mode: scale\n"));
    EXPECT_EQ(classify(pixelCell(scale.grid, 2, 0)), Cls::Free);
    EXPECT_TRUE(scale.notes.empty());
}

TEST(MapIoYaml, OriginOffTheCellGridKeepsExactSizeAndMovesLessThanHalfACell)
{
    const ScopedTempDir tmp("mapio_snap");
    const std::string& dir = tmp.path;
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
    const ScopedTempDir tmp("mapio_syntax");
    const std::string& dir = tmp.path;
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
    const ScopedTempDir tmp("mapio_yaw");
    const std::string& dir = tmp.path;
    writePgm(dir + "/m.pgm", kW, kH, kPixels);
    writeYaml(dir + "/m.yaml", "m.pgm", 0.5, "[0, 0, 1e-12]");
    EXPECT_NO_THROW(loadMap(dir + "/m.yaml"));
    writeYaml(dir + "/m.yaml", "m.pgm", 0.5, "[0, 0, 0.1]");
    const std::string msg = expectInputError([&] { loadMap(dir + "/m.yaml"); }, dir + "/m.yaml");
    EXPECT_NE(msg.find("yaw"), std::string::npos) << msg;
}

TEST(MapIoYaml, MessagesNameFileKeyAndValue)
{
    const ScopedTempDir tmp("mapio_msg");
    const std::string& dir = tmp.path;
    writePgm(dir + "/m.pgm", kW, kH, kPixels);
    writeYaml(dir + "/map.yaml", "m.pgm", -1, "[0, 0, 0]");
    EXPECT_EQ(
        expectInputError([&] { loadMap(dir + "/map.yaml"); }, dir + "/map.yaml"),
        dir + "/map.yaml: key 'resolution' = -1 must be a positive number of metres per cell");
}

// ------------------------------------------------------------------ plain images

TEST(MapIoImage, PlainPngUsesDefaultResolutionAndLowerLeftOrigin)
{
    const ScopedTempDir tmp("mapio_png");
    const std::string& dir = tmp.path;
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
    const ScopedTempDir tmp("mapio_thresh");
    const std::string& dir = tmp.path;
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
    const ScopedTempDir tmp("mapio_colour");
    const std::string& dir = tmp.path;
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
    const ScopedTempDir tmp("mapio_maxval");
    const std::string& dir = tmp.path;
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
    const ScopedTempDir tmp("mapio_bmpjpg");
    const std::string& dir = tmp.path;
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
    const ScopedTempDir tmp("mapio_gridmap");
    const std::string& dir = tmp.path;
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
    const ScopedTempDir tmp("mapio_simplemap");
    const std::string& dir = tmp.path;
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
    const ScopedTempDir tmp("mapio_errors");
    const std::string& dir = tmp.path;
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
    {"far_apart_keyframes.simplemap", "max_cells"},                       // keyframes 2000 km apart
    {"frame_count_corrupt.simplemap", "observation count = 2147483647"},  // 2^31-1
    {"grid_instead_of_keyframes.simplemap", "COccupancyGridMap2D"},       // wrong class
    {"huge_dims.jpg", "max_cells"},                    // SOF declares 65000 x 65000
    {"huge_dims.pgm", "max_cells"},                    // 200000 x 200000
    {"huge_dims.png", "max_cells"},                    // IHDR 100000 x 100000
    {"image_huge.yaml", "max_cells"},                  // names huge_dims.pgm
    {"image_not_an_image.yaml", "not a PNG"},          // names not_an_image.png
    {"image_not_found.yaml", "no such file"},          // names does_not_exist.pgm
    {"image_truncated.yaml", "cannot decode"},         // names truncated.png
    {"infinite_range.simplemap", "non-finite range"},  // a valid range of -inf
    {"keyframe_count_corrupt.simplemap", "keyframe count = 335544326"},
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
    {"ray_count_corrupt.simplemap", "ray count = 3338666021"},  // crashed MRPT
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

void expectRealMap(const std::string& path, const RealMap& r, const MapLoadOptions& opts = {})
{
    SCOPED_TRACE(path);
    const COccupancyGridMap2D g = loadMap(path, opts).grid;
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
        // An MRPT rendering: 11 grey levels between the YAML's thresholds. Read as ROS
        // trinary, they are unknown; by default (auto) they keep their probability, and the
        // cells of P(free) 0.65-0.80 (grey 166-204) are free space for the graph builder.
        MapLoadOptions trinary;
        trinary.grey_between_thresholds = "unknown";
        expectRealMap(*p, {"", 1000, 820, -26.0f, -26.0f, 13099, 167707}, trinary);
        const COccupancyGridMap2D g = loadMap(*p).grid;
        int between = 0, free_for_graph = 0;
        for (unsigned y = 0; y < g.getSizeY(); ++y)
            for (unsigned x = 0; x < g.getSizeX(); ++x)
            {
                between += classify(g.getCell(x, y)) == Cls::Other;
                free_for_graph += g.getCell(x, y) >= 0.65f;
            }
        EXPECT_GT(between, 0);
        EXPECT_GT(free_for_graph, 167707 + 20000);
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

// ------------------------------------------------------------------ serialized layouts
//
// maps/serialized_layout.h mirrors MRPT 2.5.8's readers field by field, so that length
// fields are checked before MRPT allocates. Whether it mirrors them right is measured here
// against the MRPT that is installed: objects of every version of every accepted class, with
// every flag that changes the layout, are built byte by byte; the check must consume exactly
// their bytes, and MRPT must read exactly the same bytes and find its end flag there.

namespace layout
{
using Bytes = std::vector<unsigned char>;
using mrpt_topoeval::internal::LayoutChecker;
using mrpt_topoeval::internal::LayoutError;
using mrpt_topoeval::internal::MemoryLayoutSource;

/** Little-endian field writer. */
struct W
{
    Bytes b;
    W& u8(unsigned v)
    {
        b.push_back(static_cast<unsigned char>(v));
        return *this;
    }
    W& u32(std::uint32_t v)
    {
        for (int i = 0; i < 4; ++i) b.push_back(static_cast<unsigned char>(v >> (8 * i)));
        return *this;
    }
    template <typename T>
    W& vals(int n, T v)
    {
        for (int i = 0; i < n; ++i)
        {
            const auto* p = reinterpret_cast<const unsigned char*>(&v);
            b.insert(b.end(), p, p + sizeof v);
        }
        return *this;
    }
    W& f(int n) { return vals(n, 0.5f); }
    W& d(int n) { return vals(n, 0.25); }
    W& z(int n) { return vals(n, std::uint8_t{0}); }
    W& raw(const Bytes& o)
    {
        b.insert(b.end(), o.begin(), o.end());
        return *this;
    }
};

/** CArchive::WriteObject()'s framing: 0x80 | name length, name, version, data, 0x88. */
Bytes obj(const std::string& name, int version, const Bytes& body)
{
    W w;
    w.u8(0x80 | name.size());
    w.b.insert(w.b.end(), name.begin(), name.end());
    w.u8(version).raw(body).u8(0x88);
    return w.b;
}
Bytes matrix(const std::string& cls, std::uint32_t r, std::uint32_t c)
{
    W w;
    w.u32(r).u32(c);
    cls == "CMatrixD" ? w.d(r * c) : w.f(r * c);
    return obj(cls, 0, w.b);
}
Bytes pose2(int v) { return obj("CPose2D", v, v == 0 ? W().f(3).b : W().d(3).b); }
Bytes pose3(int v)
{
    if (v == 0) return obj("mrpt::poses::CPose3D", 0, matrix("CMatrix", 4, 4));  // old name
    if (v == 1) return obj("CPose3D", 1, matrix("CMatrixD", 4, 4));
    return obj("CPose3D", v, W().d(v == 2 ? 7 : 12).b);
}
Bytes pdf2(int v)
{
    W w;
    w.raw(pose2(1));
    if (v == 0) w.raw(matrix("CMatrixF", 3, 3));
    if (v == 1) w.f(6);
    if (v == 2) w.d(6);
    return obj("CPosePDFGaussian", v, w.b);
}
Bytes pdf3() { return obj("CPose3DPDFGaussian", 1, W().raw(pose3(3)).d(21).b); }
Bytes scan(int v, std::uint32_t n, bool intensity)
{
    W w;
    w.f(1).u8(1).f(1).raw(pose3(3));
    if (v < 6) w.raw(matrix("CMatrixF", 2, 3));
    w.u32(n).f(static_cast<int>(n));
    if (v >= 1) w.z(static_cast<int>(n));
    if (v <= 3)
    {
        if (v >= 2) w.f(1);
        if (v >= 3) w.z(8);
        return obj("mrpt::obs::CObservation2DRangeScan", v, w.b);
    }
    w.f(1).z(8).f(1);
    if (v >= 5) w.u32(2).u8('l').u8('b').d(1);
    if (v >= 7) w.u8(intensity ? 1 : 0).z(intensity ? 4 * static_cast<int>(n) : 0);
    return obj("mrpt::obs::CObservation2DRangeScan", v, w.b);
}
Bytes odometry(int v, bool encoders, bool velocities)
{
    W w;
    w.raw(pose2(1)).u32(1).u8('o').z(8);
    if (v >= 1)
    {
        w.u8(encoders ? 1 : 0).z(encoders || v < 2 ? 8 : 0).u8(velocities ? 1 : 0);
        if (v < 2) w.f(2);
        if (v >= 2 && velocities) w.d(3);
    }
    return obj("CObservationOdometry", v, w.b);
}
Bytes ranges(int v)
{
    W w;
    w.f(3).u32(2);
    for (int i = 0; i < 2; ++i)
    {
        if (v >= 3) w.u8(i).u8(0);
        w.raw(pose3(i == 0 ? 3 : 2)).f(1);
    }
    if (v >= 1) w.u32(1).u8('r');
    if (v >= 2) w.z(8);
    return obj("mrpt::obs::CObservationRange", v, w.b);
}
/** An odometry action; `bool_byte` is written for hasEncodersInfo (MRPT reads odd as true). */
Bytes movement(int v, int method, int model, bool velocities, unsigned bool_byte,
               std::uint32_t particles = 10)
{
    W w;
    const bool encoders = bool_byte != 0;
    if (v <= 1)
    {
        w.raw(pdf2(2)).u32(static_cast<std::uint32_t>(method));
        if (v == 1) w.u8(velocities ? 1 : 0).f(2).u8(bool_byte).z(8);
        return obj("CActionRobotMovement2D", v, w.b);
    }
    w.u32(static_cast<std::uint32_t>(method));
    if (method == 0)
    {
        w.raw(pose2(1));
        if (v == 2) w.z(44);
        if (v >= 3) w.u32(static_cast<std::uint32_t>(model)).z(v == 3 ? 28 : 24);
        if (v >= 3) w.u32(particles).f(4);
        if (v >= 5) w.f(2);
    }
    else
    {
        w.raw(pdf2(2));
    }
    w.u8(velocities ? 1 : 0);
    if (v < 7) w.f(2);
    if (v >= 7 && velocities) w.d(3);
    w.u8(bool_byte).z(v < 7 || encoders ? 8 : 0).z(v >= 6 ? 8 : 0);
    return obj("CActionRobotMovement2D", v, w.b);
}
Bytes frame(int v)
{
    W w;
    if (v < 2) w.z(4);
    if (v == 0) w.z(8);
    w.u32(3).raw(scan(7, 3, false)).raw(odometry(2, true, true)).raw(ranges(3));
    return obj("CSensoryFrame", v, w.b);
}
/** A 2 x 2 grid of limits 0 .. 0.2 at 0.1 m (4 cells). */
Bytes grid(int v, int bits, std::uint32_t owa_length = 2)
{
    W w;
    if (v >= 2) w.u8(static_cast<unsigned>(bits));
    w.u32(2).u32(2).vals(1, 0.0f).vals(1, 0.2f).vals(1, 0.0f).vals(1, 0.2f).vals(1, 0.1f);
    w.z(4 * bits / 8);
    if (v >= 1)
    {
        w.f(1).u8(0).f(2).u8(1).z(2).f(1);           // insertionOptions
        w.z(4).f(4).z(4).f(1).u8(0).f(1).z(4).f(1);  // likelihoodOptions ...
        w.u8(1).z(4).f(1).z(4).f(1).u32(owa_length).f(2).u8(1);
        w.raw(v >= 6 ? obj("TMapGenericParams", 0, {1, 1, 1}) : Bytes{0});
    }
    if (v >= 4) w.f(2);
    if (v >= 5) w.u8(0);
    return obj("mrpt::maps::COccupancyGridMap2D", v, w.b);
}
Bytes simpleMap(int v)
{
    W w;
    w.u32(2);
    for (int i = 0; i < 2; ++i) w.raw(v == 0 ? pdf2(2) : pdf3()).raw(frame(2));
    return obj("CSimpleMap", v, w.b);
}

enum class Kind
{
    Entry,
    Grid,
    SimpleMap
};

struct Case
{
    std::string name;
    Bytes bytes;
    Kind kind = Kind::Entry;
};

std::vector<Case> everyLayout()
{
    std::vector<Case> c;
    const auto add = [&](std::string n, Bytes b, Kind k = Kind::Entry) {
        c.push_back({std::move(n), std::move(b), k});
    };
    for (int v = 0; v <= 7; ++v)
        for (const bool i : {false, true}) add("scan v" + std::to_string(v), scan(v, 3, i));
    add("scan without rays", scan(7, 0, true));
    for (int v = 0; v <= 2; ++v)
        for (const bool e : {false, true})
            for (const bool vel : {false, true})
                add("odometry v" + std::to_string(v), odometry(v, e, vel));
    for (int v = 0; v <= 3; ++v) add("ranges v" + std::to_string(v), ranges(v));
    for (int v = 0; v <= 7; ++v)
        for (int method = 0; method <= 1; ++method)
            for (int model = 0; model <= 1; ++model)
                for (const bool vel : {false, true})
                    for (const unsigned enc : {0u, 1u, 249u})
                        add("action v" + std::to_string(v) + " method " + std::to_string(method) +
                                " model " + std::to_string(model) + " encoders byte " +
                                std::to_string(enc),
                            obj("CActionCollection", 0,
                                W().u32(1).raw(movement(v, method, model, vel, enc)).b));
    for (int v = 0; v <= 2; ++v) add("sensory frame v" + std::to_string(v), frame(v));
    for (int v = 0; v <= 1; ++v) add("CPose2D v" + std::to_string(v), pose2(v));
    for (int v = 0; v <= 3; ++v) add("CPose3D v" + std::to_string(v), pose3(v));
    for (int v = 0; v <= 2; ++v) add("CPosePDFGaussian v" + std::to_string(v), pdf2(v));
    add("CPose3DPDFGaussian", pdf3());
    add("CMatrixD", matrix("CMatrixD", 2, 5));
    // Before MRPT 0.5.5: 4-byte name length, int32 version, no end flag.
    add("old-format CPose2D", W().u32(7).raw({'C', 'P', 'o', 's', 'e', '2', 'D'}).u32(1).d(3).b);
    for (int v = 0; v <= 6; ++v)
        for (const int bits : {8, 16})
            if (v >= 2 || bits == 8) add("grid v" + std::to_string(v), grid(v, bits), Kind::Grid);
    for (int v = 0; v <= 1; ++v)
        add("simple map v" + std::to_string(v), simpleMap(v), Kind::SimpleMap);
    return c;
}

mrpt_topoeval::internal::LayoutOptions gridOf4Cells()
{
    mrpt_topoeval::internal::LayoutOptions o;
    o.grid_cells = [](const mrpt_topoeval::internal::StoredGridLimits&) { return 4u; };
    return o;
}

/** Runs the check; returns its message ("" if it passed) and the bytes it consumed. */
std::pair<std::string, std::uint64_t> check(const unsigned char* data, std::size_t size, Kind kind)
{
    MemoryLayoutSource src(data, size);
    try
    {
        LayoutChecker c(src, gridOf4Cells());
        if (kind == Kind::Entry) c.rawlogEntry();
        if (kind == Kind::Grid) c.occupancyGrid();
        if (kind == Kind::SimpleMap) c.simpleMap();
    }
    catch (const LayoutError& e)
    {
        return {e.what(), src.position()};
    }
    return {"", src.position()};
}
std::pair<std::string, std::uint64_t> check(const Bytes& b, Kind kind)
{
    return check(b.data(), b.size(), kind);
}

/** MRPT reads the object from memory; returns the bytes it consumed (throws on error). */
std::uint64_t mrptReads(const unsigned char* data, std::size_t size, Kind kind,
                        mrpt::serialization::CSerializable::Ptr* out = nullptr)
{
    mrpt::io::CMemoryStream mem;
    mem.assignMemoryNotOwn(data, size);
    auto ar = mrpt::serialization::archiveFrom(mem);
    if (kind == Kind::Grid)
    {
        COccupancyGridMap2D g;
        ar >> g;
    }
    else if (kind == Kind::SimpleMap)
    {
        mrpt::maps::CSimpleMap sm;
        ar >> sm;
    }
    else
    {
        auto o = ar.ReadObject();
        if (out) *out = o;
    }
    return mem.getPosition();
}
std::uint64_t mrptReads(const Bytes& b, Kind kind,
                        mrpt::serialization::CSerializable::Ptr* out = nullptr)
{
    return mrptReads(b.data(), b.size(), kind, out);
}
}  // namespace layout

TEST(SerializedLayout, AgreesWithMrptOnEveryVersionOfEveryAcceptedClass)
{
    for (const layout::Case& c : layout::everyLayout())
    {
        SCOPED_TRACE(c.name);
        const auto [msg, used] = layout::check(c.bytes, c.kind);
        EXPECT_EQ(msg, "");
        EXPECT_EQ(used, c.bytes.size());
        std::uint64_t mrpt_used = 0;
        EXPECT_NO_THROW(mrpt_used = layout::mrptReads(c.bytes, c.kind));
        EXPECT_EQ(mrpt_used, c.bytes.size()) << "MRPT reads another layout";
    }
}

TEST(SerializedLayout, ThrunParticleCountIsWhereMrptReadsIt)
{
    // MRPT draws that many particles while reading: the check must read the same field.
    for (int v = 3; v <= 7; ++v)
    {
        SCOPED_TRACE(v);
        const layout::Bytes b = layout::movement(v, 0, 1, false, 0, 37);
        mrpt::serialization::CSerializable::Ptr o;
        ASSERT_EQ(layout::mrptReads(b, layout::Kind::Entry, &o), b.size());
        const auto a = std::dynamic_pointer_cast<mrpt::obs::CActionRobotMovement2D>(o);
        ASSERT_TRUE(a);
        const auto p =
            std::dynamic_pointer_cast<mrpt::poses::CPosePDFParticles>(a->poseChange.get_ptr());
        ASSERT_TRUE(p);
        EXPECT_EQ(p->size(), 37u);
        const std::string msg =
            layout::check(layout::movement(v, 0, 1, false, 0, 0x7FFFFFFF), layout::Kind::Entry)
                .first;
        EXPECT_NE(msg.find("nParticlesCount = 2147483647"), std::string::npos) << msg;
    }
}

TEST(SerializedLayout, LengthFieldsBeyondTheDataAreRefusedNamingFieldAndValue)
{
    using layout::Bytes;
    using layout::W;
    using Kind = layout::LayoutError::Kind;
    struct Bad
    {
        std::string name;
        Bytes bytes;
        std::string field_value;
        Kind kind;
    };
    // A scan with its ray count replaced.
    const auto scanWithRays = [](std::uint32_t n)
    {
        Bytes b = layout::scan(7, 3, false);
        const std::size_t at = 36 + 9 + layout::pose3(3).size();  // header, 3 fields, pose
        for (int i = 0; i < 4; ++i) b[at + i] = static_cast<unsigned char>(n >> (8 * i));
        return b;
    };
    // A scan without rays cut after its label length, which says 0xFFFFFF00.
    Bytes label = layout::scan(7, 0, false);
    label.resize(label.size() - 12);  // label "lb", deltaPitch, hasIntensity, end flag
    label[label.size() - 4] = 0;
    label[label.size() - 3] = label[label.size() - 2] = label[label.size() - 1] = 0xFF;
    const std::vector<Bad> bad = {
        {"4 GB label", label, "sensorLabel length = 4294967040", Kind::Truncated},
        {"scan rays over the data", scanWithRays(90'000), "ray count = 90000", Kind::Truncated},
        {"scan rays over the limit", scanWithRays(100'001), "ray count = 100001", Kind::Corrupt},
        {"frame count", layout::obj("CSensoryFrame", 2, W().u32(0x7FFFFFFF).b),
         "observation count = 2147483647", Kind::Truncated},
        {"matrix", layout::obj("CMatrixD", 0, W().u32(65536).u32(65536).b), "size = 65536 x 65536",
         Kind::Truncated},
        {"OWA_weights", layout::grid(6, 8, 1u << 30), "OWA_weights length = 1073741824",
         Kind::Truncated},
        {"3 x 4 homogeneous matrix", layout::obj("CPose3D", 1, layout::matrix("CMatrixD", 3, 4)),
         "3 x 4", Kind::Corrupt},
        {"unchecked class", layout::obj("mrpt::obs::CObservationImage", 3, Bytes(40, 0)),
         "'mrpt::obs::CObservationImage', whose layout topoeval does not check", Kind::Unchecked},
        {"unchecked class in a frame",
         layout::obj("CSensoryFrame", 2,
                     W().u32(1).raw(layout::obj("mrpt::obs::CObservationIMU", 3, Bytes(8, 0))).b),
         "'mrpt::obs::CObservationIMU', whose layout", Kind::Unchecked},
        {"unchecked action",
         layout::obj("CActionCollection", 0,
                     W().u32(1).raw(layout::obj("mrpt::obs::CObservationImage", 3, Bytes(8, 0))).b),
         "'mrpt::obs::CObservationImage', whose layout", Kind::Unchecked},
        {"null object", W().u8(0x87).raw({'n', 'u', 'l', 'l', 'p', 't', 'r'}).u8(0x88).b,
         "null object", Kind::Corrupt},
        {"unknown version", layout::obj("CPose2D", 2, W().d(3).b), "version 2 of CPose2D",
         Kind::Corrupt},
        {"ambiguous bool",
         layout::obj("CActionCollection", 0, W().u32(1).raw(layout::movement(7, 0, 0, false, 2)).b),
         "hasEncodersInfo = 2", Kind::Corrupt},
        {"bad end flag", Bytes(), "end flag = 0", Kind::Corrupt},
    };
    for (Bad c : bad)
    {
        SCOPED_TRACE(c.name);
        layout::Kind kind = layout::Kind::Entry;
        if (c.name == "OWA_weights") kind = layout::Kind::Grid;
        if (c.name == "bad end flag")
        {
            c.bytes = layout::pose2(1);
            c.bytes.back() = 0;
        }
        const auto [msg, used] = layout::check(c.bytes, kind);
        EXPECT_NE(msg.find(c.field_value), std::string::npos) << msg;
        layout::MemoryLayoutSource src(c.bytes.data(), c.bytes.size());
        try
        {
            layout::LayoutChecker ch(src, layout::gridOf4Cells());
            kind == layout::Kind::Grid ? ch.occupancyGrid() : (void)ch.rawlogEntry();
            ADD_FAILURE() << "accepted";
        }
        catch (const layout::LayoutError& e)
        {
            EXPECT_EQ(static_cast<int>(e.kind()), static_cast<int>(c.kind)) << e.what();
        }
    }
}

TEST(SerializedLayout, RealRawlogsAndMapsPassWhole)
{
    // Every entry of every shared rawlog (old and new class versions, gz): the check consumes
    // exactly what MRPT reads.
    bool any = false;
    for (const char* name :
         {"rawlogs/driving_in_office.rawlog", "rawlogs/driving_in_office_obs.rawlog",
          "rawlogs/intel.rawlog", "rawlogs/intel_fixed-action-timestamps.rawlog",
          "rawlogs/intel_obs-format.rawlog", "rawlogs/intel-corrected.rawlog",
          "rawlogs/aces-corrected.rawlog", "rawlogs/csail-corrected.rawlog",
          "rawlogs/freiburg-101-corrected.rawlog", "slam_maps/intel_icp-slam.simplemap"})
    {
        const auto p = sharedDataFile(name);
        if (!p) continue;
        any = true;
        SCOPED_TRACE(name);
        layout::Bytes data;
        mrpt::io::CFileGZInputStream in(*p);
        unsigned char buf[65536];
        for (std::size_t got; (got = in.Read(buf, sizeof buf)) > 0 && got <= sizeof buf;)
            data.insert(data.end(), buf, buf + got);
        const bool simplemap = std::string(name).find("simplemap") != std::string::npos;
        std::size_t pos = 0, entries = 0;
        while (pos < data.size())
        {
            const auto kind = simplemap ? layout::Kind::SimpleMap : layout::Kind::Entry;
            const auto [msg, used] = layout::check(data.data() + pos, data.size() - pos, kind);
            ASSERT_EQ(msg, "") << "entry " << entries;
            ASSERT_EQ(layout::mrptReads(data.data() + pos, data.size() - pos, kind), used)
                << "entry " << entries;
            pos += used;
            ++entries;
        }
        EXPECT_GT(entries, 0u);
    }
    if (!any) GTEST_SKIP() << "../shared/data is not available";
}

TEST(MapIoGridmap, LengthFieldsAreCheckedBeforeMrptAllocates)
{
    const ScopedTempDir tmp("mapio_layout");
    const std::string& dir = tmp.path;
    const auto write = [&](const std::string& name, const layout::Bytes& b)
    {
        std::ofstream(dir + "/" + name, std::ios::binary)
            .write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
        return dir + "/" + name;
    };
    // The hand-made grid loads (4 cells) ...
    const std::string ok = write("ok.gridmap", layout::grid(6, 8));
    EXPECT_EQ(loadMap(ok).grid.getSizeX(), 2u);
    // ... and with OWA_weights declaring 2^30 floats (MRPT allocated 4 GB for it) is refused.
    const std::string owa_path = write("owa.gridmap", layout::grid(6, 8, 1u << 30));
    std::string msg = expectInputError([&] { loadMap(owa_path); }, owa_path);
    EXPECT_NE(msg.find("OWA_weights length = 1073741824"), std::string::npos) << msg;
    // Limits far from the origin: MRPT's float arithmetic no longer follows ours.
    layout::Bytes far = layout::grid(6, 8);
    const float x_min = 1e7f, x_max = 1e7f + 2.0f;  // 10^8 cells of 0.1 m from the origin
    std::memcpy(&far[33 + 1 + 8], &x_min, 4);       // after the header, bits and size_x, size_y
    std::memcpy(&far[33 + 1 + 8 + 4], &x_max, 4);
    const std::string far_path = write("far.gridmap", far);
    msg = expectInputError([&] { loadMap(far_path); }, far_path);
    EXPECT_NE(msg.find("2^24 cells"), std::string::npos) << msg;
    // 16-bit cells: twice the bytes.
    const std::string wide = write("wide.gridmap", layout::grid(6, 16));
    EXPECT_EQ(loadMap(wide).grid.getSizeY(), 2u);
}

}  // namespace

// mapFromCells() (Python Map.from_array): cells land where an OccupancyGrid puts them (row 0
// at the lowest y), both encodings classify as documented, bad arrays are refused by name.
TEST(MapFromCells, CellsLandInOccupancyGridOrderWithTheirClasses)
{
    using mrpt_topoeval::CellEncoding;
    using mrpt_topoeval::mapFromCells;
    const mrpt_topoeval::MapLoadOptions opts;
    // 3 columns x 2 rows; row 0 is y in [1, 1.1), the lower row.
    const std::vector<double> probabilities = {0.0, 1.0, NAN, 0.3, 0.9, 0.5};
    const auto m = mapFromCells(probabilities, 3, 2, 0.1, 1.0, 1.0,
                                CellEncoding::OccupancyProbability, opts, "array");
    EXPECT_EQ(m.format, "array");
    EXPECT_EQ(m.grid.getSizeX(), 3u);
    EXPECT_EQ(m.grid.getSizeY(), 2u);
    EXPECT_NEAR(m.grid.getXMin(), 1.0, 1e-6);
    EXPECT_NEAR(m.grid.getYMin(), 1.0, 1e-6);
    EXPECT_NEAR(m.grid.getCell(0, 0), 1.0, 0.01);  // P(free) = 1 - P(occupied)
    EXPECT_NEAR(m.grid.getCell(1, 0), 0.0, 0.01);
    EXPECT_NEAR(m.grid.getCell(2, 0), 0.5, 0.01);  // NaN = unknown
    EXPECT_NEAR(m.grid.getCell(0, 1), 0.7, 0.01);  // kept as a probability
    EXPECT_NEAR(m.grid.getCell(1, 1), 0.1, 0.01);

    // ROS values: -1 unknown, 0 free, 100 occupied, between classified by the thresholds.
    const std::vector<double> ros = {0, 100, -1, 10, 70, 50};
    const auto r =
        mapFromCells(ros, 3, 2, 0.1, 0.0, 0.0, CellEncoding::RosOccupancyGrid, opts, "ros");
    const std::vector<double> expected_free = {1.0, 0.0, 0.5, 1.0, 0.0, 0.5};
    for (int i = 0; i < 6; ++i)
        EXPECT_NEAR(r.grid.getCell(i % 3, i / 3), expected_free[i], 0.01) << "cell " << i;

    const auto message = [&](const std::vector<double>& cells, std::size_t w, std::size_t h,
                             CellEncoding enc, double res = 0.1)
    {
        try
        {
            mapFromCells(cells, w, h, res, 0.0, 0.0, enc, opts, "arr");
        }
        catch (const mrpt_topoeval::InputError& e)
        {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(message({0.0, 1.5}, 2, 1, CellEncoding::OccupancyProbability),
              "arr: cell (row 0, column 1) = 1.5 violates 0 <= occupancy probability <= 1 "
              "(NaN = unknown)");
    EXPECT_EQ(message({0.0, 101}, 2, 1, CellEncoding::RosOccupancyGrid),
              "arr: cell (row 0, column 1) = 101 is not an OccupancyGrid value (-1 unknown, "
              "0..100)");
    EXPECT_EQ(message({}, 0, 1, CellEncoding::RosOccupancyGrid), "arr: a 1 x 0 array has no cells");
    EXPECT_EQ(message({0.0}, 1, 1, CellEncoding::RosOccupancyGrid, -1),
              "arr: resolution_m = -1 violates resolution_m > 0");
}
