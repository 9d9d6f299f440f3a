/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "rawlog/RawlogReader.h"

#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRange.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_topoeval/errors.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <new>
#include <sstream>
#include <vector>

#include "maps/serialized_layout.h"

namespace fs = std::filesystem;

namespace mrpt_topoeval::rawlog
{
RawlogReader::RawlogReader(const std::string& path, std::uint64_t max_entry_bytes,
                           bool read_unchecked_classes)
    : m_path(path),
      m_max_entry_bytes(max_entry_bytes),
      m_read_unchecked_classes(read_unchecked_classes)
{
    std::error_code ec;
    if (!fs::exists(path, ec)) throw InputError(path + ": no such file");
    if (fs::is_directory(path, ec)) throw InputError(path + ": is a folder, not a rawlog");
    m_file_bytes = fs::file_size(path, ec);
    if (ec) throw InputError(path + ": cannot read the file size: " + ec.message());
    {
        // The gzip magic decides whether the file position is a share of the file.
        std::ifstream f(path, std::ios::binary);
        if (!f) throw InputError(path + ": cannot open for reading");
        unsigned char magic[2] = {0, 0};
        f.read(reinterpret_cast<char*>(magic), 2);
        m_gzipped = f.gcount() == 2 && magic[0] == 0x1f && magic[1] == 0x8b;
    }
    if (!m_in.open(path)) throw InputError(path + ": cannot open for reading");
    // MRPT registers a class when its library loads. Naming the classes the layout check
    // accepts links their libraries into any program that reads rawlogs, even one that uses
    // nothing else of them (with --as-needed, MRPT would otherwise report them unregistered).
    static const bool linked = []
    {
        for (const auto* c :
             {CLASS_ID(mrpt::obs::CSensoryFrame), CLASS_ID(mrpt::obs::CActionCollection),
              CLASS_ID(mrpt::obs::CActionRobotMovement2D),
              CLASS_ID(mrpt::obs::CObservation2DRangeScan),
              CLASS_ID(mrpt::obs::CObservationOdometry), CLASS_ID(mrpt::obs::CObservationRange),
              CLASS_ID(mrpt::poses::CPosePDFGaussian), CLASS_ID(mrpt::poses::CPose3DPDFGaussian)})
            if (!c) return false;
        return true;
    }();
    (void)linked;
}

namespace
{
/** MRPT's exception texts span several lines ("==== MRPT exception ====", "Message: ..."):
 * the line that says what happened. */
std::string meaningfulLine(const std::string& what)
{
    std::istringstream ss(what);
    std::string line, first;
    while (std::getline(ss, line))
    {
        const auto b = line.find_first_not_of(" \t");
        if (b == std::string::npos || line.compare(b, 4, "====") == 0) continue;
        line = line.substr(b);
        if (line.rfind("Message:", 0) == 0) return line.substr(line.find_first_not_of(" ", 8));
        if (first.empty()) first = line;
    }
    return first.empty() ? std::string("unknown error") : first;
}

/** The bytes of one entry, read from the rawlog as the layout check asks for them and kept,
 * so that MRPT then deserializes exactly those bytes from memory. The layout check never asks
 * for more than the entry's size limit, nor (plain files) for more than the file still holds,
 * so the buffer is bounded before any byte is read. */
class EntrySource final : public internal::LayoutSource
{
public:
    EntrySource(mrpt::io::CFileGZInputStream& in, std::uint64_t limit, std::uint64_t start,
                std::uint64_t file_bytes, bool gzipped, std::vector<unsigned char>& out)
        : m_in(in),
          m_limit(limit),
          // The rest of a plain file bounds the entry too; a gz file's rest is unknown.
          m_file_left(gzipped ? UINT64_MAX : file_bytes - std::min(start, file_bytes)),
          m_out(out)
    {
        m_out.clear();
    }

    Result take(void* dst, std::uint64_t n) override
    {
        if (n > m_limit - m_out.size()) return Result::Limit;
        if (n > m_file_left - std::min<std::uint64_t>(m_out.size(), m_file_left))
            return Result::End;  // a plain file too short for it: nothing to buffer
        const std::size_t old = m_out.size();
        m_out.resize(old + static_cast<std::size_t>(n));
        std::size_t done = 0;
        while (done < n)
        {
            const std::size_t want = static_cast<std::size_t>(n) - done;
            std::size_t got = 0;
            try
            {
                got = m_in.Read(m_out.data() + old + done, want);
            }
            catch (const std::exception&)
            {
                got = 0;
            }
            // zlib's -1 (corrupt or cut gzip data) arrives as a huge count: the data ends here.
            if (got == 0 || got > want)
            {
                m_gzip_error = got > want;
                m_out.resize(old + done);
                return Result::End;
            }
            done += got;
        }
        if (dst && n) std::copy_n(m_out.data() + old, n, static_cast<unsigned char*>(dst));
        return Result::Ok;
    }
    std::uint64_t position() const override { return m_out.size(); }
    std::uint64_t available() const override
    {
        const std::uint64_t cap = std::min(m_limit, m_file_left);
        return cap - std::min<std::uint64_t>(m_out.size(), cap);
    }
    bool availableIsLimit() const override { return m_limit <= m_file_left; }
    std::string limitText() const override
    {
        return "the limit of " + std::to_string(m_limit) + " bytes per entry";
    }
    bool gzipError() const { return m_gzip_error; }

private:
    mrpt::io::CFileGZInputStream& m_in;
    std::uint64_t m_limit;
    std::uint64_t m_file_left;
    std::vector<unsigned char>& m_out;
    bool m_gzip_error = false;
};

/** The bytes of an entry already read by the layout check, then the rest of the rawlog: what
 * MRPT reads an entry of a class the check does not know from. */
class PrefixedStream final : public mrpt::io::CStream
{
public:
    PrefixedStream(const std::vector<unsigned char>& prefix, mrpt::io::CFileGZInputStream& rest)
        : m_prefix(prefix), m_rest(rest)
    {
    }
    size_t Read(void* buffer, size_t count) override
    {
        auto* out = static_cast<unsigned char*>(buffer);
        const std::size_t from_prefix = std::min(count, m_prefix.size() - m_pos_prefix);
        std::copy_n(m_prefix.data() + m_pos_prefix, from_prefix, out);
        m_pos_prefix += from_prefix;
        std::size_t done = from_prefix;
        if (done < count)
        {
            const std::size_t want = count - done;
            const std::size_t got = m_rest.Read(out + done, want);
            // zlib's -1 (corrupt or cut gzip data) arrives as a huge count: the data ends.
            if (got <= want)
            {
                done += got;
                m_rest_bytes += got;
            }
        }
        return done;
    }
    size_t Write(const void*, size_t) override { return 0; }
    uint64_t Seek(int64_t, mrpt::io::CStream::TSeekOrigin) override { return getPosition(); }
    uint64_t getTotalBytesCount() const override { return m_prefix.size() + m_rest_bytes; }
    uint64_t getPosition() const override { return m_pos_prefix + m_rest_bytes; }

private:
    const std::vector<unsigned char>& m_prefix;
    mrpt::io::CFileGZInputStream& m_rest;
    std::size_t m_pos_prefix = 0;
    std::uint64_t m_rest_bytes = 0;
};
}  // namespace

bool RawlogReader::atEndOfData()
{
    try
    {
        char byte = 0;
        return m_in.Read(&byte, 1) == 0;
    }
    catch (const std::exception&)
    {
        // zlib fails on a cut .gz stream: that is a truncation too.
        return m_gzipped;
    }
}

std::uint64_t RawlogReader::bytesRead() const { return m_in.getPosition(); }

double RawlogReader::fractionRead() const
{
    if (m_gzipped || m_file_bytes == 0) return -1.0;
    return std::min(1.0, static_cast<double>(bytesRead()) / static_cast<double>(m_file_bytes));
}

RawlogReader::Status RawlogReader::next(mrpt::serialization::CSerializable::Ptr& obj,
                                        std::string& why)
{
    obj.reset();
    const std::string entry = "entry " + std::to_string(m_entries);
    // 1. The entry's layout is checked field by field while its bytes are read (see
    //    maps/serialized_layout.h): MRPT sizes its containers from counts in the file
    //    before reading the data they announce, so a count the entry cannot hold is refused
    //    here, before MRPT allocates anything for it.
    std::vector<unsigned char> bytes;
    EntrySource src(m_in, m_max_entry_bytes, bytesRead(), m_file_bytes, m_gzipped, bytes);
    try
    {
        internal::LayoutChecker(src).rawlogEntry();
    }
    catch (const internal::LayoutError& e)
    {
        using Kind = internal::LayoutError::Kind;
        if (e.kind() == Kind::Unchecked && m_read_unchecked_classes)
            return readUnchecked(bytes, obj, why);
        if (e.kind() == Kind::Truncated)
        {
            if (src.position() == 0 && !src.gzipError()) return Status::EndOfFile;
            why = "the file ends inside " + entry + " (truncated" +
                  (src.gzipError() ? ": corrupt or cut gzip data" : "") + "): " + e.what();
            return Status::Truncated;
        }
        why = e.kind() == Kind::TooLarge ? entry + " is too large: " + std::string(e.what())
                                         : entry + " cannot be decoded: " + std::string(e.what());
        return Status::Corrupt;
    }
    catch (const std::bad_alloc&)
    {
        why = entry + " cannot be buffered (out of memory)";
        return Status::Corrupt;
    }

    // 2. MRPT deserializes exactly those bytes.
    try
    {
        mrpt::io::CMemoryStream mem;
        mem.assignMemoryNotOwn(bytes.data(), bytes.size());
        auto ar = mrpt::serialization::archiveFrom(mem);
        obj = ar.ReadObject();
        if (mem.getPosition() != bytes.size())
        {
            obj.reset();
            why = entry + " cannot be decoded: MRPT read " + std::to_string(mem.getPosition()) +
                  " of its " + std::to_string(bytes.size()) +
                  " bytes (a topoeval layout check disagrees with MRPT: please report)";
            return Status::Corrupt;
        }
    }
    catch (const std::bad_alloc&)
    {
        obj.reset();
        why = entry + " cannot be decoded (out of memory)";
        return Status::Corrupt;
    }
    catch (const std::exception& e)
    {
        obj.reset();
        why = entry + " cannot be decoded: " + meaningfulLine(e.what());
        return Status::Corrupt;
    }
    if (!obj)
    {
        why = entry + " is a null object";
        return Status::Corrupt;
    }
    ++m_entries;
    return Status::Object;
}

RawlogReader::Status RawlogReader::readUnchecked(const std::vector<unsigned char>& checked,
                                                 mrpt::serialization::CSerializable::Ptr& obj,
                                                 std::string& why)
{
    // An entry holding a class the layout check does not know (a camera, an IMU...): MRPT
    // reads it from the bytes checked so far and the rest of the file, as MRPT's own apps do.
    // Its size limit can only be checked afterwards (doc/reliability.md, residual risk).
    const std::string entry = "entry " + std::to_string(m_entries);
    PrefixedStream in(checked, m_in);
    try
    {
        auto ar = mrpt::serialization::archiveFrom(in);
        obj = ar.ReadObject();
    }
    catch (const mrpt::serialization::CExceptionEOF&)
    {
        why = "the file ends inside " + entry + " (truncated)";
        return Status::Truncated;
    }
    catch (const std::bad_alloc&)
    {
        obj.reset();
        why = entry + " cannot be decoded (it claims an absurd size)";
        return Status::Corrupt;
    }
    catch (const std::exception& e)
    {
        // MRPT reports a short read inside an object's body as a generic exception: the file
        // ending right there is a truncation, anything else a corrupt entry.
        obj.reset();
        const bool at_end = atEndOfData();
        why = entry + " cannot be decoded" +
              (at_end ? " (the file ends inside it: truncated)" : "") + ": " +
              meaningfulLine(e.what());
        return at_end ? Status::Truncated : Status::Corrupt;
    }
    if (!obj)
    {
        why = entry + " is a null object";
        return Status::Corrupt;
    }
    if (in.getPosition() > m_max_entry_bytes)
    {
        obj.reset();
        why = entry + " is " + std::to_string(in.getPosition()) + " bytes, over the limit of " +
              std::to_string(m_max_entry_bytes) + " bytes per entry";
        return Status::Corrupt;
    }
    ++m_entries;
    return Status::Object;
}

}  // namespace mrpt_topoeval::rawlog
