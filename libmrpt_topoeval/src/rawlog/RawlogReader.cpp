/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "rawlog/RawlogReader.h"

#include <mrpt/serialization/CArchive.h>
#include <mrpt_topoeval/errors.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <new>
#include <sstream>

namespace fs = std::filesystem;

namespace mrpt_topoeval::rawlog
{
RawlogReader::RawlogReader(const std::string& path, std::uint64_t max_entry_bytes)
    : m_path(path), m_max_entry_bytes(max_entry_bytes)
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
    const std::uint64_t before = bytesRead();
    try
    {
        auto ar = mrpt::serialization::archiveFrom(m_in);
        obj = ar.ReadObject();
    }
    catch (const mrpt::serialization::CExceptionEOF&)
    {
        // MRPT reports the end of data the same way between and inside objects: nothing
        // consumed means a clean end.
        if (bytesRead() == before) return Status::EndOfFile;
        why = "the file ends inside entry " + std::to_string(m_entries) + " (truncated)";
        return Status::Truncated;
    }
    catch (const std::bad_alloc&)
    {
        // A damaged length field asked for more memory than there is.
        why =
            "entry " + std::to_string(m_entries) + " cannot be decoded (it claims an absurd size)";
        return Status::Corrupt;
    }
    catch (const std::exception& e)
    {
        // MRPT reports a short read inside an object's body as a generic exception: the file
        // ending right there is a truncation, anything else a corrupt entry.
        const bool at_end = atEndOfData();
        why = "entry " + std::to_string(m_entries) + " cannot be decoded" +
              (at_end ? " (the file ends inside it: truncated)" : "") + ": " +
              meaningfulLine(e.what());
        return at_end ? Status::Truncated : Status::Corrupt;
    }
    if (!obj)
    {
        why = "entry " + std::to_string(m_entries) + " is a null object";
        return Status::Corrupt;
    }
    if (bytesRead() - before > m_max_entry_bytes)
    {
        why = "entry " + std::to_string(m_entries) + " is " + std::to_string(bytesRead() - before) +
              " bytes, over the limit of " + std::to_string(m_max_entry_bytes) + " bytes per entry";
        obj.reset();
        return Status::Corrupt;
    }
    ++m_entries;
    return Status::Object;
}

}  // namespace mrpt_topoeval::rawlog
