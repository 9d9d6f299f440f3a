/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Atomic outputs: complete files or none, never replacing a file without permission, never
// leaving temporary files behind.

#include <gtest/gtest.h>
#include <mrpt/img/CImage.h>
#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/json/JsonWriter.h>
#include <mrpt_topoeval/output.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "cli_runner.h"
#include "test_paths.h"

namespace fs = std::filesystem;
using mrpt_topoeval::OutputError;
using mrpt_topoeval::writeFileAtomic;

using mrpt_topoeval::testing::readText;
using mrpt_topoeval::testing::ScopedTempDir;

namespace
{
/** Names of everything in `dir` (hidden files included: that is where temp files hide). */
std::set<std::string> listing(const std::string& dir)
{
    std::set<std::string> names;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        names.insert(fs::relative(e.path(), dir).string());
    return names;
}

std::string expectOutputError(const std::string& path, const std::string& bytes, bool overwrite)
{
    try
    {
        writeFileAtomic(path, bytes, overwrite);
    }
    catch (const OutputError& e)
    {
        return e.what();
    }
    ADD_FAILURE() << "no OutputError writing " << path;
    return "";
}
}  // namespace

TEST(Output, WritesANewFileAndNothingElse)
{
    const ScopedTempDir dir_tmp("output");
    const std::string& dir = dir_tmp.path;
    const std::string path = dir + "/out.json";
    const std::string bytes = std::string("{\"a\": 1}\n") + std::string(100000, 'x');
    writeFileAtomic(path, bytes, false);
    EXPECT_EQ(readText(path), bytes);
    EXPECT_EQ(listing(dir), std::set<std::string>{"out.json"});
}

TEST(Output, RefusesToReplaceAnExistingFile)
{
    const ScopedTempDir dir_tmp("output");
    const std::string& dir = dir_tmp.path;
    const std::string path = dir + "/out.json";
    writeFileAtomic(path, "old", false);
    const std::string msg = expectOutputError(path, "new", false);
    EXPECT_EQ(msg, path + ": exists; pass --force to replace it");
    EXPECT_EQ(readText(path), "old");
    EXPECT_EQ(listing(dir), std::set<std::string>{"out.json"});
}

TEST(Output, ReplacesAnExistingFileWhenAllowed)
{
    const ScopedTempDir dir_tmp("output");
    const std::string& dir = dir_tmp.path;
    const std::string path = dir + "/out.json";
    writeFileAtomic(path, "old content, longer than the new one", false);
    writeFileAtomic(path, "new", true);
    EXPECT_EQ(readText(path), "new");
    EXPECT_EQ(listing(dir), std::set<std::string>{"out.json"});
}

TEST(Output, CreatesMissingFolders)
{
    const ScopedTempDir dir_tmp("output");
    const std::string& dir = dir_tmp.path;
    const std::string path = dir + "/a/b/out.json";
    writeFileAtomic(path, "x", false);
    EXPECT_EQ(readText(path), "x");
}

TEST(Output, RefusesFolders)
{
    const ScopedTempDir dir_tmp("output");
    const std::string& dir = dir_tmp.path;
    fs::create_directory(dir + "/sub");
    EXPECT_EQ(expectOutputError(dir + "/sub", "x", true), dir + "/sub: is a folder");
    EXPECT_EQ(listing(dir), std::set<std::string>{"sub"});
    EXPECT_EQ(expectOutputError("", "x", true), "output file name is empty");
}

TEST(Output, ParentThatIsAFileFailsCleanly)
{
    const ScopedTempDir dir_tmp("output");
    const std::string& dir = dir_tmp.path;
    writeFileAtomic(dir + "/file", "data", false);
    const std::string msg = expectOutputError(dir + "/file/out.json", "x", false);
    EXPECT_EQ(msg.rfind(dir + "/file/out.json: ", 0), 0u) << msg;
    EXPECT_EQ(readText(dir + "/file"), "data");
    EXPECT_EQ(listing(dir), std::set<std::string>{"file"});
}

TEST(Output, NonWritableFolderFailsWithoutDebris)
{
    if (::geteuid() == 0) GTEST_SKIP() << "root ignores folder permissions";
    const ScopedTempDir dir_tmp("output");
    const std::string& dir = dir_tmp.path;
    const std::string ro = dir + "/ro";
    fs::create_directory(ro);
    fs::permissions(ro, fs::perms::owner_read | fs::perms::owner_exec);
    const std::string msg = expectOutputError(ro + "/out.json", "x", false);
    fs::permissions(ro, fs::perms::owner_all);
    EXPECT_EQ(msg.rfind(ro + "/out.json: cannot create a file in", 0), 0u) << msg;
    EXPECT_TRUE(listing(ro).empty());
}

TEST(Output, FailedWriteRemovesTheTemporaryFile)
{
    // A file size limit makes write() fail after the temporary file exists (also for root).
    const ScopedTempDir dir_tmp("output");
    const std::string& dir = dir_tmp.path;
    const std::string path = dir + "/big.bin";
    writeFileAtomic(path, "previous", false);

    rlimit old{};
    ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
    rlimit small = old;
    small.rlim_cur = 4096;
    const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);  // EFBIG instead of a signal
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
    const std::string msg = expectOutputError(path, std::string(100000, 'y'), true);
    ::setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, old_handler);

    EXPECT_EQ(msg.rfind(path + ": write failed: ", 0), 0u) << msg;
    EXPECT_EQ(readText(path), "previous");  // the old file is intact
    EXPECT_EQ(listing(dir), std::set<std::string>{"big.bin"});
}

TEST(Output, WritesPng)
{
    const ScopedTempDir dir_tmp("output");
    const std::string& dir = dir_tmp.path;
    mrpt::img::CImage img(20, 10, mrpt::img::CH_RGB);
    img.filledRectangle(0, 0, 19, 9, mrpt::img::TColor(10, 200, 30));
    const std::string path = dir + "/pic.png";
    mrpt_topoeval::writePngAtomic(path, img, false);
    const std::string bytes = readText(path);
    ASSERT_GT(bytes.size(), 8u);
    EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));

    mrpt::img::CImage back;
    ASSERT_TRUE(back.loadFromFile(path));
    EXPECT_EQ(back.getWidth(), 20u);
    EXPECT_EQ(back.getHeight(), 10u);

    EXPECT_THROW(mrpt_topoeval::writePngAtomic(path, img, false), OutputError);
    EXPECT_THROW(mrpt_topoeval::writePngAtomic(dir + "/empty.png", mrpt::img::CImage(), false),
                 OutputError);
    EXPECT_EQ(listing(dir), std::set<std::string>{"pic.png"});
}

// The apps' own JSON files (rawlog and series report.json) name the user's files, whose names
// may hold any byte: the text must stay valid JSON and UTF-8.
TEST(Output, JsonQuoteEscapesAndKeepsUtf8Valid)
{
    EXPECT_EQ(mrpt_topoeval::JsonWriter::quote("plain"), "\"plain\"");
    EXPECT_EQ(mrpt_topoeval::JsonWriter::quote("a\"b\\c"), "\"a\\\"b\\\\c\"");
    EXPECT_EQ(mrpt_topoeval::JsonWriter::quote("l1\nl2\t\x01"), "\"l1\\nl2\\t\\u0001\"");
    EXPECT_EQ(mrpt_topoeval::JsonWriter::quote("caf\xC3\xA9.png"), "\"caf\xC3\xA9.png\"")
        << "valid UTF-8 is kept";
    EXPECT_EQ(mrpt_topoeval::JsonWriter::quote("bad\xFF.png"), "\"bad\xEF\xBF\xBD.png\"")
        << "a stray byte is U+FFFD";
    EXPECT_EQ(mrpt_topoeval::JsonWriter::quote(std::string("nul\0x", 5)), "\"nul\\u0000x\"");
}

// The one-line form of messages that the command prints and Python's exceptions carry.
TEST(MessageOnOneLine, FoldsLineBreaksIntoSemicolons)
{
    using mrpt_topoeval::messageOnOneLine;
    EXPECT_EQ(messageOnOneLine("a.yaml: bad"), "a.yaml: bad");
    EXPECT_EQ(messageOnOneLine("first\nsecond\r\n\nthird\n"), "first; second; third");
    EXPECT_EQ(messageOnOneLine("\n\nlead"), "lead");
    EXPECT_EQ(messageOnOneLine(""), "");
}
