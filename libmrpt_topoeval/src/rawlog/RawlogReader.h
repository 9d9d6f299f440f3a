/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// A rawlog read one serialized object at a time, so that no entry is lost: MRPT's
// CRawlog::getActionObservationPairOrObservation() silently drops unpaired entries.

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/serialization/CSerializable.h>

#include <cstdint>
#include <string>
#include <vector>

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

    /** Opens `path` (gz or plain). Entries of classes whose layout is not checked before MRPT
     * reads them (cameras, IMU, GPS...: maps/serialized_layout.h) are read by MRPT as they
     * are if `read_unchecked_classes`, else refused as corrupt (the fuzz target's choice: it
     * exercises the check, not MRPT's readers of every sensor).
     * \throws InputError if it is missing or unreadable. */
    RawlogReader(const std::string& path, std::uint64_t max_entry_bytes,
                 bool read_unchecked_classes = true);

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

private:
    /** True if no byte is left (after a failed read). */
    bool atEndOfData();
    /** The rest of an entry whose class the layout check does not know, read by MRPT from the
     * bytes `checked` so far and the rest of the file. */
    Status readUnchecked(const std::vector<unsigned char>& checked,
                         mrpt::serialization::CSerializable::Ptr& obj, std::string& why);

    std::string m_path;
    mrpt::io::CFileGZInputStream m_in;
    std::uint64_t m_max_entry_bytes;
    bool m_read_unchecked_classes = true;
    std::uint64_t m_file_bytes = 0;
    bool m_gzipped = false;
    std::size_t m_entries = 0;
};

}  // namespace mrpt_topoeval::rawlog
