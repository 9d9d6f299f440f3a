/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// A rawlog read one serialized object at a time, so that no entry is lost: MRPT's
// CRawlog::getActionObservationPairOrObservation() silently drops unpaired entries.

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/serialization/CSerializable.h>

#include <cstdint>
#include <string>

namespace mrpt_topoeval::rawlog
{
class RawlogReader
{
public:
    enum class Status
    {
        Object,     //!< `obj` holds the next entry.
        EndOfFile,  //!< Clean end: the file ends between two entries.
        Truncated,  //!< The file ends inside an entry.
        Corrupt,    //!< An entry cannot be decoded or exceeds the size limit.
    };

    /** Opens `path` (gz or plain). \throws InputError if it is missing or unreadable. */
    RawlogReader(const std::string& path, std::uint64_t max_entry_bytes);

    /** Reads the next entry. On Truncated / Corrupt, `why` says what went wrong (without the
     * file name); the reader must not be used afterwards. */
    Status next(mrpt::serialization::CSerializable::Ptr& obj, std::string& why);

    /** Entries read so far (the index of the next one). */
    std::size_t entries() const { return m_entries; }
    /** Uncompressed bytes consumed so far. */
    std::uint64_t bytesRead() const;
    /** File size on disk [bytes]. */
    std::uint64_t fileBytes() const { return m_file_bytes; }
    /** Share of the file consumed, or -1 when unknown (gz: only the uncompressed position is
     * known). */
    double fractionRead() const;
    bool gzipped() const { return m_gzipped; }

private:
    /** True if no byte is left (after a failed read). */
    bool atEndOfData();

    std::string m_path;
    mrpt::io::CFileGZInputStream m_in;
    std::uint64_t m_max_entry_bytes;
    std::uint64_t m_file_bytes = 0;
    bool m_gzipped = false;
    std::size_t m_entries = 0;
};

}  // namespace mrpt_topoeval::rawlog
