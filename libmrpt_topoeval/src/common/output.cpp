/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include <fcntl.h>
#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/output.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace mrpt_topoeval
{
namespace
{
std::string errnoText(int err) { return std::strerror(err); }

/** Removes the temporary file unless it was handed over by a successful rename, so no
 * failure leaves debris next to the user's files. */
class TempFileGuard
{
public:
    explicit TempFileGuard(std::string path) : m_path(std::move(path)) {}
    ~TempFileGuard()
    {
        if (m_fd >= 0) ::close(m_fd);
        if (!m_released) ::unlink(m_path.c_str());
    }
    TempFileGuard(const TempFileGuard&) = delete;
    TempFileGuard& operator=(const TempFileGuard&) = delete;

    void setFd(int fd) { m_fd = fd; }
    /** Closes the descriptor; returns the errno of a failed close (0 on success), which can
     * be the first report of a failed write on network file systems. */
    int close()
    {
        const int rc = ::close(m_fd);
        m_fd = -1;
        return rc == 0 ? 0 : errno;
    }
    void release() { m_released = true; }

private:
    std::string m_path;
    int m_fd = -1;
    bool m_released = false;
};

/** ".NAME.tmp.<pid>.<counter>" next to the target: the same file system, so the final
 * rename is atomic; hidden, so a crash leaves nothing that looks like a result. */
fs::path tempPathFor(const fs::path& target)
{
    static std::atomic<unsigned> counter{0};
    return target.parent_path() / ("." + target.filename().string() + ".tmp." +
                                   std::to_string(::getpid()) + "." + std::to_string(counter++));
}

/** Moves `tmp` to `target`; without `overwrite` the kernel refuses to replace an existing
 * target (RENAME_NOREPLACE), so a file created meanwhile by someone else is never lost. */
void moveIntoPlace(const fs::path& tmp, const fs::path& target, bool overwrite,
                   const std::string& name)
{
    if (!overwrite)
    {
        if (::renameat2(AT_FDCWD, tmp.c_str(), AT_FDCWD, target.c_str(), RENAME_NOREPLACE) == 0)
            return;
        const int err = errno;
        if (err == EEXIST) throw OutputError(name + ": exists; pass --force to replace it");
        // File systems without RENAME_NOREPLACE: a hard link also refuses to replace.
        if (err != EINVAL && err != ENOSYS && err != ENOTSUP)
            throw OutputError(name +
                              ": cannot rename the temporary file into place: " + errnoText(err));
        if (::link(tmp.c_str(), target.c_str()) == 0)
        {
            ::unlink(tmp.c_str());
            return;
        }
        const int lerr = errno;
        if (lerr == EEXIST) throw OutputError(name + ": exists; pass --force to replace it");
        // Last resort (e.g. FAT): check, then rename; only a concurrent writer can slip in.
        std::error_code ec;
        if (fs::exists(target, ec))
            throw OutputError(name + ": exists; pass --force to replace it");
    }
    if (std::rename(tmp.c_str(), target.c_str()) != 0)
        throw OutputError(name +
                          ": cannot rename the temporary file into place: " + errnoText(errno));
}

/** Makes the rename itself durable; failures only cost durability, not correctness. */
void syncFolder(const fs::path& folder)
{
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
    if (fd < 0) return;
    (void)::fsync(fd);
    ::close(fd);
}
}  // namespace

void writeFileAtomic(const std::string& path, const std::string& bytes, bool overwrite)
{
    if (path.empty()) throw OutputError("output file name is empty");
    const fs::path target(path);
    if (target.filename().empty() || target.filename() == "." || target.filename() == "..")
        throw OutputError(path + ": not a file name");

    std::error_code ec;
    const fs::file_status st = fs::status(target, ec);
    if (fs::is_directory(st)) throw OutputError(path + ": is a folder");
    if (fs::exists(st) && !overwrite)
        throw OutputError(path + ": exists; pass --force to replace it");

    // A missing output folder is created (like `mkdir -p`): asking for out/run1/graph.json is
    // a clear request, and creating folders never loses anything.
    const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    if (!fs::exists(folder, ec))
    {
        fs::create_directories(folder, ec);
        if (ec)
            throw OutputError(path + ": cannot create folder '" + folder.string() +
                              "': " + ec.message());
    }
    else if (!fs::is_directory(folder, ec))
        throw OutputError(path + ": '" + folder.string() + "' is not a folder");

    const fs::path tmp = tempPathFor(folder / target.filename());
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0)
        throw OutputError(path + ": cannot create a file in '" + folder.string() +
                          "': " + errnoText(errno));
    TempFileGuard guard(tmp.string());
    guard.setFd(fd);

    const char* p = bytes.data();
    std::size_t left = bytes.size();
    while (left > 0)
    {
        const ssize_t n = ::write(fd, p, left);
        if (n < 0)
        {
            if (errno == EINTR) continue;
            throw OutputError(path + ": write failed: " + errnoText(errno));
        }
        p += n;
        left -= static_cast<std::size_t>(n);
    }
    if (::fsync(fd) != 0 && errno != EINVAL)  // EINVAL: special files that cannot sync
        throw OutputError(path + ": write failed: " + errnoText(errno));
    if (const int err = guard.close(); err != 0)
        throw OutputError(path + ": write failed: " + errnoText(err));

    moveIntoPlace(tmp, target, overwrite, path);
    guard.release();
    syncFolder(folder);
}

void writePngAtomic(const std::string& path, const mrpt::img::CImage& img, bool overwrite)
{
    // MRPT throws on access to an uninitialised image: check before touching the cv::Mat.
    if (img.isEmpty() || img.asCvMatRef().empty())
        throw OutputError(path + ": the image to write is empty");
    const cv::Mat& mat = img.asCvMatRef();
    std::vector<uchar> buf;
    bool ok = false;
    try
    {
        ok = cv::imencode(".png", mat, buf);
    }
    catch (const cv::Exception& e)
    {
        throw OutputError(path + ": PNG encoding failed: " + e.msg);
    }
    if (!ok) throw OutputError(path + ": PNG encoding failed");
    writeFileAtomic(path, std::string(buf.begin(), buf.end()), overwrite);
}

}  // namespace mrpt_topoeval
