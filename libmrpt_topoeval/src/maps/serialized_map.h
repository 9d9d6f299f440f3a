/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// Reading MRPT serialized map files (.gridmap, .simplemap, gzip or plain) safely: shared by
// format_gridmap.cpp and format_simplemap.cpp.

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CStream.h>
#include <mrpt/serialization/CArchive.h>

#include <cstdint>
#include <new>
#include <string>

#include "common/error_text.h"
#include "maps/map_formats.h"
#include "maps/serialized_layout.h"

namespace mrpt_topoeval::map_formats
{
/** Reads through CFileGZInputStream (gzip or plain) but checks what it ignores:
 * - its Read() returns zlib's -1 on corrupt or truncated data as a huge byte count, which
 *   MRPT's deserializers take for success and then parse stale buffer contents: here such a
 *   read throws, and the reason is kept, because MRPT replaces any error inside an object by
 *   a generic "Cannot read object due to EOF";
 * - MRPT accepts a short read as long as it is not empty, so a file cut inside a field leaves
 *   part of that field uninitialised (a garbage scan size then crashes MRPT): here Read()
 *   delivers all the bytes asked for or none. */
class CheckedGzInput : public mrpt::io::CStream
{
public:
    explicit CheckedGzInput(const std::string& path) : m_in(path)
    {
        if (!m_in.fileOpenCorrectly()) fail(path, "cannot be opened");
    }

    /** Up to `count` bytes; fewer only at the end of the file. */
    size_t readSome(void* buffer, size_t count)
    {
        auto* p = static_cast<unsigned char*>(buffer);
        size_t done = 0;
        while (done < count)
        {
            const size_t got = m_in.Read(p + done, count - done);
            if (got == 0)
            {
                m_hit_end = true;
                break;
            }
            if (got > count - done)
            {
                m_error = "corrupt or truncated gzip data";
                throw std::runtime_error(m_error);
            }
            done += got;
        }
        m_position += done;
        return done;
    }

    size_t Read(void* buffer, size_t count) override
    {
        return readSome(buffer, count) == count ? count : 0;
    }
    size_t Write(const void*, size_t) override
    {
        throw std::logic_error("CheckedGzInput is read-only");
    }
    uint64_t Seek(int64_t, TSeekOrigin) override
    {
        throw std::logic_error("CheckedGzInput cannot seek");
    }
    uint64_t getTotalBytesCount() const override { return m_in.getTotalBytesCount(); }
    uint64_t getPosition() const override { return m_position; }

    /** Why the last read failed, if it was the stream (not the data) that failed. */
    const std::string& error() const { return m_error; }
    /** Whether a read asked for bytes past the end of the (decompressed) file. */
    bool hitEnd() const { return m_hit_end; }

private:
    mrpt::io::CFileGZInputStream m_in;
    uint64_t m_position = 0;
    std::string m_error;
    bool m_hit_end = false;
};

/** The start of an MRPT serialized object (CArchive::WriteObject). */
struct ObjectHeader
{
    std::string class_name;  //!< As stored, e.g. "mrpt::maps::COccupancyGridMap2D".
    int version = 0;
};

/** Reads the class name and version of the object at the start of a serialized file without
 * deserializing it, so that a file of another class gets its own message. */
ObjectHeader peekObjectHeader(const std::string& path);
/** "mrpt::maps::COccupancyGridMap2D" -> "COccupancyGridMap2D" (old files omit namespaces). */
std::string bareClassName(const std::string& name);
void expectClass(const std::string& path, const ObjectHeader& h, const std::string& expected,
                 const std::string& format_name);
/** Turns a refused layout into the one-line message of a map file. */
[[noreturn]] void failLayout(const std::string& path, const internal::LayoutError& e,
                             const std::string& gzip_error);

/** Deserializes one object, turning MRPT's errors into a one-line message. */
template <typename T>
void readObject(const std::string& path, T& obj, const std::string& what)
{
    CheckedGzInput in(path);
    try
    {
        mrpt::serialization::archiveFrom(in) >> obj;
    }
    catch (const std::bad_alloc&)
    {
        throw;
    }
    catch (const std::exception& e)
    {
        if (!in.error().empty()) fail(path, in.error());
        if (in.hitEnd()) fail(path, "truncated: the file ends inside its " + what);
        fail(path, "corrupt " + what + " (MRPT: " + internal::oneLine(e) + ")");
    }
}

}  // namespace mrpt_topoeval::map_formats
