/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once
// Walks the bytes of MRPT-serialized objects and checks every length field against the bytes
// that follow it, BEFORE MRPT deserializes them (doc/reliability.md, "Length fields").
//
// Why: MRPT 2.5's deserializers resize their containers to the counts stored in the file and
// only then read the data those counts announce (std::string, std::vector, scan rays, matrix
// sizes, sensory-frame observations, Thrun-model particles that are not even stored). A few
// changed bytes make them allocate and zero gigabytes, or ask MRPT's aligned allocator for more
// than it can give (it returns null, and MRPT writes through it). A stream wrapper cannot help:
// the allocation happens before the first read of the data. So the layout of every class we
// accept is mirrored here from MRPT 2.5.8's serializeFrom(), version by version, and an object
// reaches MRPT only after its whole layout fits in the data; then every allocation MRPT makes
// while reading it is bounded by the object's size in bytes (or by an explicit limit below).
//
// Where MRPT allows any object (a rawlog entry, an observation of a sensory frame, an action),
// one of another class (a camera, an IMU, a GPS...) ends the check with Kind::Unchecked: its
// layout is unknown here, so its extent is too, and the caller lets MRPT read it as it is (real
// rawlogs hold other sensors; nothing bounds what MRPT allocates for those). Anywhere else a
// class that does not belong is refused. Null objects are refused too (MRPT never writes them
// inside these classes, and dereferences some of them after reading).
//
// Used by the map loader and the rawlog reader; the layouts are in serialized_layout.cpp.

#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace mrpt_topoeval::internal
{
/** Why a layout was refused. what() is one line without the file name. */
class LayoutError : public std::runtime_error
{
public:
    enum class Kind
    {
        Truncated,  //!< The data ends inside the object.
        Corrupt,    //!< A field holds a value MRPT would misread, or the class is not accepted.
        TooLarge,   //!< A field asks for more bytes than the source allows (its limit).
        /** A rawlog entry, observation or action of a class whose layout is not mirrored here
         * (a camera, an IMU, a GPS...): the check cannot go on, the caller decides. */
        Unchecked
    };
    LayoutError(Kind kind, const std::string& what) : std::runtime_error(what), m_kind(kind) {}
    Kind kind() const { return m_kind; }

private:
    Kind m_kind;
};

/** The bytes being checked, consumed front to back. */
class LayoutSource
{
public:
    enum class Result
    {
        Ok,
        End,   //!< The data ends before the requested bytes.
        Limit  //!< The requested bytes lie beyond what the source may deliver.
    };
    virtual ~LayoutSource() = default;
    /** Consumes the next `n` bytes, copied to `dst` unless it is null. */
    virtual Result take(void* dst, std::uint64_t n) = 0;
    /** Bytes consumed so far. */
    virtual std::uint64_t position() const = 0;
    /** An upper bound of the bytes that can still be consumed. */
    virtual std::uint64_t available() const = 0;
    /** Whether available() is a limit of the source (true) or the end of the data (false). */
    virtual bool availableIsLimit() const = 0;
    /** The limit in words, for messages: "the limit of 1048576 bytes per rawlog entry". */
    virtual std::string limitText() const = 0;
};

/** A complete serialized file in memory. */
class MemoryLayoutSource final : public LayoutSource
{
public:
    MemoryLayoutSource(const unsigned char* data, std::size_t size) : m_data(data), m_size(size) {}
    Result take(void* dst, std::uint64_t n) override;
    std::uint64_t position() const override { return m_pos; }
    std::uint64_t available() const override { return m_size - m_pos; }
    bool availableIsLimit() const override { return false; }
    std::string limitText() const override { return "the end of the file"; }

private:
    const unsigned char* m_data;
    std::size_t m_size;
    std::size_t m_pos = 0;
};

/** The five floats a serialized COccupancyGridMap2D gives to setSize(). */
struct StoredGridLimits
{
    float x_min = 0, x_max = 0, y_min = 0, y_max = 0, resolution = 0;
};

struct LayoutOptions
{
    /** Rays per 2D scan. MRPT's grid insertion puts a scan's rays in alloca() buffers on the
     * stack (100k rays: 800 kB); real scanners give < 10k. */
    std::uint32_t max_scan_rays = 100'000;
    /** Particles of a Thrun motion model: MRPT draws `nParticlesCount` samples when it reads
     * an odometry action, a count stored in the file with no data behind it (default 300). */
    std::uint32_t max_particles = 100'000;
    /** The exact number of cells MRPT will allocate and read for a grid with these limits, or
     * a LayoutError if the grid is refused (set by the map loader: it knows max_cells and runs
     * MRPT's own float arithmetic). Grids are refused when it is not set. */
    std::function<std::uint64_t(const StoredGridLimits&)> grid_cells;
};

/** Walks one serialized object (see the file comment). Every method throws LayoutError. */
class LayoutChecker
{
public:
    explicit LayoutChecker(LayoutSource& src, LayoutOptions opts = {});
    ~LayoutChecker();
    LayoutChecker(const LayoutChecker&) = delete;
    LayoutChecker& operator=(const LayoutChecker&) = delete;

    /** One rawlog entry (a sensory frame, an action collection, an observation, or one of the
     * small classes below); returns its class name as stored. */
    std::string rawlogEntry();
    /** The object of a .gridmap file. */
    void occupancyGrid();
    /** The object of a .simplemap file. */
    void simpleMap();

    /** The classes a rawlog entry may hold, for messages. */
    static const char* rawlogClasses();

private:
    class Walker;  // the layouts, mirrored from MRPT (serialized_layout.cpp)
    std::unique_ptr<Walker> m_walker;
};

}  // namespace mrpt_topoeval::internal
