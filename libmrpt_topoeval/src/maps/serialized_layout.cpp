/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The serialized layouts of the classes topoeval checks before MRPT reads them, mirrored from
// MRPT 2.5.8's serializeFrom(), version by version (maps/serialized_layout.h says why).

#include "maps/serialized_layout.h"

#include <cstring>
#include <limits>

namespace mrpt_topoeval::internal
{
MemoryLayoutSource::Result MemoryLayoutSource::take(void* dst, std::uint64_t n)
{
    if (n > m_size - m_pos) return Result::End;
    if (dst && n) std::memcpy(dst, m_data + m_pos, static_cast<std::size_t>(n));
    m_pos += static_cast<std::size_t>(n);
    return Result::Ok;
}

class LayoutChecker::Walker
{
public:
    Walker(LayoutSource& src, LayoutOptions opts) : m_src(src), m_opts(std::move(opts)) {}

    /** Where an object appears: decides which classes MRPT would accept there. */
    enum class Role
    {
        RawlogEntry,
        Observation,  //!< In a sensory frame: ReadObject<CObservation>.
        Action,       //!< In an action collection: ReadObject<CAction>.
        PosePdf2D,    //!< ReadObject<CPosePDF>.
        PosePdf3D,    //!< ReadObject<CPose3DPDF>.
        SensoryFrame,
        Pose2D,  //!< A CPose2D member: ReadObject(&existing) wants that exact class.
        Pose3D,
        MatrixF,
        MatrixD,
        MapParams,
        Grid,
        SimpleMap
    };

    struct Header
    {
        std::string stored;  //!< As written, e.g. "mrpt::obs::CSensoryFrame".
        std::string bare;    //!< Without the namespace: MRPT's registry looks names up so.
        unsigned version = 0;
        bool old_format = false;  //!< Before MRPT 0.5.5: int32 version, no end flag.
    };

    static std::string num(std::uint64_t v) { return std::to_string(v); }

    std::string where() const
    {
        std::string s;
        for (const std::string& c : m_ctx) s += (s.empty() ? "" : " > ") + c;
        return s;
    }
    [[noreturn]] void fail(LayoutError::Kind kind, const std::string& what) const
    {
        const std::string w = where();
        throw LayoutError(kind, w.empty() ? what : w + ": " + what);
    }
    [[noreturn]] void corrupt(const std::string& what) const
    {
        fail(LayoutError::Kind::Corrupt, what);
    }

    /** Refuses a field that needs `n` bytes when the source cannot hold them. */
    void checkAvailable(std::uint64_t n, const std::string& field_value)
    {
        if (n <= m_src.available()) return;
        if (m_src.availableIsLimit())
            fail(LayoutError::Kind::TooLarge,
                 field_value + " needs " + num(n) + " bytes, over " + m_src.limitText());
        // The data cannot say whether it was cut or the count is wrong: both are reported as
        // the data ending inside the field, with the count.
        fail(LayoutError::Kind::Truncated, field_value + " needs " + num(n) +
                                               " bytes but the data ends " +
                                               num(m_src.available()) + " bytes later");
    }

    void take(void* dst, std::uint64_t n, const std::string& field)
    {
        switch (m_src.take(dst, n))
        {
            case LayoutSource::Result::Ok:
                return;
            case LayoutSource::Result::End:
                fail(LayoutError::Kind::Truncated, "the data ends inside " + field);
            case LayoutSource::Result::Limit:
                fail(LayoutError::Kind::TooLarge, field + " lies beyond " + m_src.limitText());
        }
    }

    template <typename T>
    T value(const std::string& field)
    {
        // MRPT writes little-endian, as this machine is (MRPT itself does not swap on x86).
        T v{};
        take(&v, sizeof(T), field);
        return v;
    }
    bool boolean(const std::string& field)
    {
        // MRPT reads a bool's byte as is. Real files hold other values than 0 and 1 (249 in
        // intel_fixed-action-timestamps.rawlog), which MRPT's compiled code takes as true
        // whether it tests the byte or its lowest bit; an even value > 0 would be true for
        // one test and false for the other, so the layout that follows is unknown.
        const auto b = value<std::uint8_t>(field);
        if (b != 0 && b % 2 == 0)
            corrupt(field + " = " + num(b) + " is not a boolean MRPT reads unambiguously");
        return b != 0;
    }
    void skip(std::uint64_t n, const std::string& field)
    {
        checkAvailable(n, field);
        take(nullptr, n, field);
    }

    /** A uint32 element count followed by `count * bytes_each` bytes of data. */
    std::uint32_t count(const std::string& field, std::uint64_t bytes_each)
    {
        const auto n = value<std::uint32_t>(field);
        checkAvailable(n * bytes_each, field + " = " + num(n));
        return n;
    }
    /** A uint32 count and that many elements of `bytes_each` bytes (std::vector, string). */
    void array(const std::string& field, std::uint64_t bytes_each)
    {
        const std::uint32_t n = count(field + " length", bytes_each);
        skip(n * bytes_each, field);
    }
    /** A count of objects; each takes at least 4 bytes (header, 1-character name, version,
     * end flag), so a count the data cannot hold is refused before MRPT sizes its container. */
    std::uint32_t objectCount(const std::string& field, std::uint64_t objects_each = 1)
    {
        return count(field, 4 * objects_each);
    }

    Header header(const std::string& what)
    {
        Header h;
        const auto first = value<std::uint8_t>(what + " header");
        h.old_format = (first & 0x80) == 0;
        if (h.old_format)
        {
            unsigned char zeros[3];
            take(zeros, 3, what + " header");
            if (zeros[0] || zeros[1] || zeros[2])
                corrupt(what + " does not start with an MRPT object header");
        }
        const unsigned len = first & 0x7F;
        if (len > 120)  // MRPT's own limit
            corrupt(what + " class name length = " + num(len) + " (MRPT allows 120)");
        char name[128] = {};
        take(name, len, what + " class name");
        h.stored.assign(name, strnlen(name, len));  // MRPT keeps the name up to a NUL byte
        const auto colons = h.stored.rfind("::");
        h.bare = colons == std::string::npos ? h.stored : h.stored.substr(colons + 2);
        if (h.stored == "nullptr") corrupt(what + " is a null object");
        if (h.old_format)
        {
            const auto v = value<std::int32_t>(what + " version");
            if (v < 0 || v > 254) corrupt(what + " version = " + num(v) + " (MRPT allows 0..254)");
            h.version = static_cast<unsigned>(v);
        }
        else
        {
            h.version = value<std::uint8_t>(what + " version");
        }
        return h;
    }

    void checkVersion(const Header& h, unsigned max_version, unsigned min_version = 0)
    {
        if (h.version < min_version || h.version > max_version)
            corrupt("serialization version " + num(h.version) + " of " + h.bare +
                    " is not one MRPT 2.5 reads (" + num(min_version) + ".." + num(max_version) +
                    ")");
    }

    static bool accepts(Role role, const std::string& c)
    {
        switch (role)
        {
            case Role::RawlogEntry:
                return c == "CSensoryFrame" || c == "CActionCollection" ||
                       c == "CObservation2DRangeScan" || c == "CObservationOdometry" ||
                       c == "CObservationRange" || c == "CActionRobotMovement2D" ||
                       c == "CPose2D" || c == "CPose3D" || c == "CPosePDFGaussian" ||
                       c == "CPose3DPDFGaussian" || c == "CMatrixF" || c == "CMatrix" ||
                       c == "CMatrixD";
            case Role::Observation:
                return c == "CObservation2DRangeScan" || c == "CObservationOdometry" ||
                       c == "CObservationRange";
            case Role::Action:
                return c == "CActionRobotMovement2D";
            case Role::PosePdf2D:
                return c == "CPosePDFGaussian";
            case Role::PosePdf3D:
                return c == "CPose3DPDFGaussian";
            case Role::SensoryFrame:
                return c == "CSensoryFrame";
            case Role::Pose2D:
                return c == "CPose2D";
            case Role::Pose3D:
                return c == "CPose3D";
            case Role::MatrixF:
                return c == "CMatrixF" || c == "CMatrix";  // MRPT registers the old name
            case Role::MatrixD:
                return c == "CMatrixD";
            case Role::MapParams:
                return c == "TMapGenericParams";
            case Role::Grid:
                return c == "COccupancyGridMap2D";
            case Role::SimpleMap:
                return c == "CSimpleMap";
        }
        return false;
    }

    /** Rows and columns of a CMatrixF / CMatrixD, read by object(). */
    struct MatrixSize
    {
        std::uint32_t rows = 0, cols = 0;
    };

    /** Reads one object where `role` allows it; returns its stored class name. */
    std::string object(Role role, const std::string& what, MatrixSize* matrix = nullptr)
    {
        const Header h = header(what);
        if (!accepts(role, h.bare))
        {
            // Real rawlogs and simple maps hold other sensors too: where MRPT allows any
            // object, one of a class not mirrored here ends the check, and the caller lets
            // MRPT read the rest as it is (a residual risk, doc/reliability.md).
            if (role == Role::RawlogEntry || role == Role::Observation || role == Role::Action)
                throw LayoutError(LayoutError::Kind::Unchecked,
                                  what + " holds a '" + h.stored +
                                      "', whose layout topoeval does not check (checked: " +
                                      rawlogClasses() + ")");
            corrupt(what + " holds a '" + h.stored + "', not what MRPT expects there");
        }
        // Nesting is shallow in every accepted class; a deep chain is damage.
        if (m_ctx.size() > 16) corrupt(what + " is nested too deeply");
        const std::string cls = h.bare + " v" + num(h.version);
        m_ctx.push_back(m_ctx.empty() ? cls : what + " (" + cls + ")");
        body(h, matrix);
        m_ctx.pop_back();
        if (!h.old_format)
        {
            const auto flag = value<std::uint8_t>(what + " end flag");
            if (flag != 0x88)
                corrupt(what + " (" + h.bare + ") end flag = " + num(flag) + ", not 0x88");
        }
        return h.stored;
    }

    void body(const Header& h, MatrixSize* matrix)
    {
        const std::string& c = h.bare;
        if (c == "CSensoryFrame") return sensoryFrame(h);
        if (c == "CActionCollection") return actionCollection(h);
        if (c == "CObservation2DRangeScan") return scan(h);
        if (c == "CObservationOdometry") return odometry(h);
        if (c == "CObservationRange") return ranges(h);
        if (c == "CActionRobotMovement2D") return robotMovement2D(h);
        if (c == "CPose2D") return pose2D(h);
        if (c == "CPose3D") return pose3D(h);
        if (c == "CPosePDFGaussian") return posePdfGaussian(h);
        if (c == "CPose3DPDFGaussian") return pose3DPdfGaussian(h);
        if (c == "CMatrixF" || c == "CMatrix") return matrixBody(h, 4, matrix);
        if (c == "CMatrixD") return matrixBody(h, 8, matrix);
        if (c == "TMapGenericParams") return mapParams(h);
        if (c == "COccupancyGridMap2D") return grid(h);
        if (c == "CSimpleMap") return simpleMapBody(h);
        corrupt("no layout for class " + c);  // accepts() and body() disagree: a bug here
    }

    // --- One method per class: MRPT 2.5.8's serializeFrom(), field by field. ---

    void sensoryFrame(const Header& h)
    {
        checkVersion(h, 2);
        if (h.version < 2) skip(4, "ID");          // removed in version 2
        if (h.version == 0) skip(8, "timestamp");  // moved into the observations in version 1
        const std::uint32_t n = objectCount("observation count");
        for (std::uint32_t i = 0; i < n; ++i)
            object(Role::Observation, "observation " + num(i) + " of " + num(n));
    }

    void actionCollection(const Header& h)
    {
        checkVersion(h, 0);
        const std::uint32_t n = objectCount("action count");
        for (std::uint32_t i = 0; i < n; ++i)
            object(Role::Action, "action " + num(i) + " of " + num(n));
    }

    void scan(const Header& h)
    {
        checkVersion(h, 7);
        skip(4 + 1 + 4, "aperture, rightToLeft, maxRange");
        object(Role::Pose3D, "sensorPose");
        if (h.version < 6) object(Role::MatrixF, "covSensorPose");  // removed in version 6
        // resizeScan(N) allocates ranges, validity flags and intensities before any is read.
        const std::uint32_t n = value<std::uint32_t>("ray count");
        if (n > m_opts.max_scan_rays)
            corrupt("ray count = " + num(n) + " is over " + num(m_opts.max_scan_rays) +
                    " rays per scan");
        const bool has_validity = h.version >= 1;
        checkAvailable(std::uint64_t{n} * (has_validity ? 5 : 4), "ray count = " + num(n));
        skip(std::uint64_t{n} * 4, "ranges");
        if (has_validity) skip(n, "validity flags");
        if (h.version <= 3)
        {
            if (h.version >= 2) skip(4, "stdError");
            if (h.version >= 3) skip(8, "timestamp");
            return;
        }
        skip(4 + 8 + 4, "stdError, timestamp, beamAperture");
        if (h.version >= 5)
        {
            array("sensorLabel", 1);
            skip(8, "deltaPitch");  // a double
        }
        if (h.version >= 7 && boolean("hasIntensity") && n > 0)
            skip(std::uint64_t{n} * 4, "intensities");
    }

    void odometry(const Header& h)
    {
        checkVersion(h, 2);
        object(Role::Pose2D, "odometry");
        array("sensorLabel", 1);
        skip(8, "timestamp");
        if (h.version < 1) return;
        const bool encoders = boolean("hasEncodersInfo");
        if (encoders || h.version < 2) skip(8, "encoder ticks");
        const bool velocities = boolean("hasVelocities");
        if (h.version < 2)
            skip(8, "velocities");
        else if (velocities)
            skip(24, "velocityLocal");
    }

    void ranges(const Header& h)
    {
        checkVersion(h, 3);
        skip(3 * 4, "minSensorDistance, maxSensorDistance, sensorConeAperture");
        // Each measurement: a CPose3D object (>= 4 bytes) and a float, sensorID since v3.
        const std::uint32_t n = count("measurement count", 8);
        for (std::uint32_t i = 0; i < n; ++i)
        {
            if (h.version >= 3) skip(2, "sensorID");
            object(Role::Pose3D, "measurement " + num(i) + " of " + num(n) + " sensorPose");
            skip(4, "sensedDistance");
        }
        if (h.version >= 1) array("sensorLabel", 1);
        if (h.version >= 2) skip(8, "timestamp");
    }

    void robotMovement2D(const Header& h)
    {
        checkVersion(h, 7);
        if (h.version <= 1)
        {
            object(Role::PosePdf2D, "poseChange");
            skip(4, "estimationMethod");
            if (h.version == 1)
            {
                boolean("hasVelocities");
                skip(8, "velocities");  // two floats in MRPT 2.5's reader
                boolean("hasEncodersInfo");
                skip(8, "encoder ticks");
            }
            return;
        }
        const auto method = value<std::int32_t>("estimationMethod");
        if (method == 0)  // emOdometry: MRPT rebuilds the pose PDF from the motion model
        {
            object(Role::Pose2D, "rawOdometryIncrementReading");
            if (h.version == 2)
            {
                skip(44, "motion model options (version 2)");
            }
            else
            {
                const auto model = value<std::int32_t>("modelSelection");
                // Version 3: 28 bytes in MRPT 2.5.8's reader (measured against it; older MRPT
                // sources read 5 doubles there).
                skip(h.version == 3 ? 28 : 6 * 4, "Gaussian model options");
                const auto particles = value<std::uint32_t>("nParticlesCount");
                // mmThrun draws that many particles, with no data behind the count.
                if (model != 0 && particles > m_opts.max_particles)
                    corrupt("Thrun model nParticlesCount = " + num(particles) + " is over " +
                            num(m_opts.max_particles));
                skip(4 * 4, "Thrun model options");
                if (h.version >= 5) skip(2 * 4, "Thrun model additional noise");
            }
        }
        else
        {
            object(Role::PosePdf2D, "poseChange");
        }
        const bool velocities = boolean("hasVelocities");
        if (h.version >= 7)
        {
            if (velocities) skip(24, "velocityLocal");
        }
        else
        {
            skip(8, "velocities");  // two floats in MRPT 2.5's reader (not doubles)
        }
        const bool encoders = boolean("hasEncodersInfo");
        if (h.version < 7 || encoders) skip(8, "encoder ticks");
        if (h.version >= 6) skip(8, "timestamp");
    }

    void pose2D(const Header& h)
    {
        checkVersion(h, 1);
        skip(h.version == 0 ? 3 * 4 : 3 * 8, "x, y, phi");
    }

    void pose3D(const Header& h)
    {
        checkVersion(h, 3);
        if (h.version <= 1)
        {
            // A 4 x 4 homogeneous matrix; MRPT checks its size only after reading it.
            MatrixSize m;
            object(h.version == 0 ? Role::MatrixF : Role::MatrixD, "homogeneous matrix", &m);
            if (m.rows != 4 || m.cols != 4)
                corrupt("homogeneous matrix is " + num(m.rows) + " x " + num(m.cols) +
                        ", not 4 x 4");
            return;
        }
        skip(h.version == 2 ? 7 * 8 : 12 * 8, "coordinates");
    }

    void posePdfGaussian(const Header& h)
    {
        checkVersion(h, 2);
        object(Role::Pose2D, "mean");
        if (h.version == 0)
        {
            // Assigned to a fixed 3 x 3 matrix without a size check (Eigen, NDEBUG).
            MatrixSize m;
            object(Role::MatrixF, "cov", &m);
            if (m.rows != 3 || m.cols != 3)
                corrupt("cov is " + num(m.rows) + " x " + num(m.cols) + ", not 3 x 3");
            return;
        }
        skip(h.version == 1 ? 6 * 4 : 6 * 8, "cov");  // upper triangle of 3 x 3
    }

    void pose3DPdfGaussian(const Header& h)
    {
        checkVersion(h, 1, 1);
        object(Role::Pose3D, "mean");
        skip(21 * 8, "cov");  // upper triangle of 6 x 6
    }

    void matrixBody(const Header& h, std::uint64_t bytes_each, MatrixSize* out)
    {
        checkVersion(h, 0);
        const auto rows = value<std::uint32_t>("rows");
        const auto cols = value<std::uint32_t>("cols");
        // setSize(rows, cols) allocates before the data is read.
        const std::uint64_t n = std::uint64_t{rows} * cols;
        const std::string what = "size = " + num(rows) + " x " + num(cols);
        if (n > std::numeric_limits<std::uint64_t>::max() / bytes_each) corrupt(what);
        checkAvailable(n * bytes_each, what);
        skip(n * bytes_each, "matrix elements");
        if (out) *out = {rows, cols};
    }

    void mapParams(const Header& h)
    {
        checkVersion(h, 0);
        for (const char* f :
             {"enableSaveAs3DObject", "enableObservationLikelihood", "enableObservationInsertion"})
            boolean(f);
    }

    void grid(const Header& h)
    {
        checkVersion(h, 6);
        unsigned bits = 8;
        if (h.version >= 2)
        {
            bits = value<std::uint8_t>("bits per cell");
            if (bits != 8 && bits != 16) corrupt("bits per cell = " + num(bits) + " (8 or 16)");
        }
        skip(8, "size_x, size_y");  // MRPT ignores them: setSize() derives the size below
        StoredGridLimits g;
        g.x_min = value<float>("x_min");
        g.x_max = value<float>("x_max");
        g.y_min = value<float>("y_min");
        g.y_max = value<float>("y_max");
        g.resolution = value<float>("resolution");
        if (!m_opts.grid_cells) corrupt("grids are not accepted here");
        const std::uint64_t cells = m_opts.grid_cells(g);
        const std::uint64_t bytes = cells * (bits / 8);
        checkAvailable(bytes, "the cells (" + num(cells) + " of " + num(bits) + " bits)");
        skip(bytes, "the cells (" + num(cells) + " declared)");
        if (h.version >= 1)
        {
            // insertionOptions, then likelihoodOptions up to OWA_weights.
            skip(4, "mapAltitude");
            boolean("useMapAltitude");
            skip(4 + 4, "maxDistanceInsertion, maxOccupancyUpdateCertainty");
            boolean("considerInvalidRangesAsFreeSpace");
            skip(2 + 4, "decimation, horizontalTolerance");
            skip(4 + 4 * 4 + 4 + 4, "likelihoodMethod, LF_stdHit .. LF_maxCorrsDistance");
            boolean("LF_alternateAverageMethod");
            skip(4 + 4 + 4, "MI_exponent, MI_skip_rays, MI_ratio_max_distance");
            boolean("rayTracing_useDistanceFilter");
            skip(4 + 4 + 4 + 4, "rayTracing_decimation .. consensus_pow");
            array("OWA_weights", 4);
            boolean("enableLikelihoodCache");
            if (h.version >= 6)
                object(Role::MapParams, "genericMapParams");
            else
                boolean("disableSaveAs3DObject");
        }
        if (h.version >= 4) skip(8, "CFD feature sizes");
        if (h.version >= 5) boolean("wideningBeamsWithDistance");
    }

    void simpleMapBody(const Header& h)
    {
        checkVersion(h, 1);
        const std::uint32_t n = objectCount("keyframe count", 2);
        for (std::uint32_t i = 0; i < n; ++i)
        {
            const std::string kf = "keyframe " + num(i) + " of " + num(n);
            object(h.version == 0 ? Role::PosePdf2D : Role::PosePdf3D, kf + " pose");
            object(Role::SensoryFrame, kf + " observations");
        }
    }

    LayoutSource& m_src;
    LayoutOptions m_opts;
    std::vector<std::string> m_ctx;
};

LayoutChecker::LayoutChecker(LayoutSource& src, LayoutOptions opts)
    : m_walker(std::make_unique<Walker>(src, std::move(opts)))
{
}

LayoutChecker::~LayoutChecker() = default;

std::string LayoutChecker::rawlogEntry()
{
    return m_walker->object(Walker::Role::RawlogEntry, "entry");
}

void LayoutChecker::occupancyGrid() { m_walker->object(Walker::Role::Grid, "grid"); }

void LayoutChecker::simpleMap() { m_walker->object(Walker::Role::SimpleMap, "simple map"); }

const char* LayoutChecker::rawlogClasses()
{
    return "CSensoryFrame, CActionCollection, CObservation2DRangeScan, CObservationOdometry, "
           "CObservationRange, CActionRobotMovement2D, poses and pose PDFs";
}

}  // namespace mrpt_topoeval::internal
