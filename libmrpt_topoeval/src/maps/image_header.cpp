/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "maps/image_header.h"

#include <mrpt_topoeval/errors.h>

#include <array>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>

namespace mrpt_topoeval::internal
{
namespace
{
[[noreturn]] void fail(const std::string& path, const std::string& what)
{
    throw InputError(path + ": " + what);
}

std::uint32_t be16(const unsigned char* p) { return (std::uint32_t(p[0]) << 8) | p[1]; }
std::uint32_t be32(const unsigned char* p)
{
    return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) |
           p[3];
}
std::uint32_t le16(const unsigned char* p) { return p[0] | (std::uint32_t(p[1]) << 8); }
std::uint32_t le32(const unsigned char* p)
{
    return p[0] | (std::uint32_t(p[1]) << 8) | (std::uint32_t(p[2]) << 16) |
           (std::uint32_t(p[3]) << 24);
}

std::string sizeText(std::uint64_t w, std::uint64_t h)
{
    return std::to_string(w) + " x " + std::to_string(h);
}

/** Fills `buf` from the start of the file; returns how many bytes there were. */
template <std::size_t N>
std::size_t readPrefix(std::ifstream& f, std::array<unsigned char, N>& buf)
{
    f.clear();
    f.seekg(0);
    f.read(reinterpret_cast<char*>(buf.data()), static_cast<std::streamsize>(N));
    return static_cast<std::size_t>(f.gcount());
}

// PNG: the 8-byte signature is followed by the IHDR chunk (length, "IHDR", width, height,
// all big-endian), which the specification requires to come first.
ImageHeader readPng(const std::string& path, std::ifstream& f)
{
    std::array<unsigned char, 24> b{};
    if (readPrefix(f, b) < b.size()) fail(path, "truncated PNG header");
    if (std::memcmp(b.data() + 12, "IHDR", 4) != 0)
        fail(path, "invalid PNG header (the first chunk is not IHDR)");
    ImageHeader h;
    h.format = ImageFormat::Png;
    h.width = be32(b.data() + 16);
    h.height = be32(b.data() + 20);
    // The PNG specification limits both sizes to 1 .. 2^31-1.
    const std::uint64_t png_max = 0x7fffffffULL;
    if (h.width == 0 || h.height == 0 || h.width > png_max || h.height > png_max)
        fail(path, "invalid PNG header (declares " + sizeText(h.width, h.height) + " pixels)");
    return h;
}

/** Netpbm header tokens: decimal numbers separated by whitespace, with `#` comments up to
 * the end of a line anywhere between them. */
class PnmTokenizer
{
public:
    PnmTokenizer(const std::string& path, std::ifstream& f) : m_path(path), m_f(f) {}

    std::uint64_t number(const char* what)
    {
        int c = skipSpaceAndComments();
        if (c == EOF) fail(m_path, "truncated Netpbm header (no " + std::string(what) + ")");
        if (c < '0' || c > '9')
            fail(m_path, "invalid Netpbm header (" + std::string(what) + " is not a number)");
        std::uint64_t v = 0;
        // Saturate rather than wrap: an absurd declared size must stay absurd.
        const std::uint64_t cap = std::numeric_limits<std::uint64_t>::max() / 16;
        while (c >= '0' && c <= '9')
        {
            if (v < cap) v = v * 10 + static_cast<std::uint64_t>(c - '0');
            c = get();
        }
        return v;
    }

private:
    int get()
    {
        // A real header is a few dozen bytes; comments may add some, but not megabytes.
        if (++m_count > kMaxHeaderBytes) fail(m_path, "invalid Netpbm header (too long)");
        return m_f.get();
    }
    int skipSpaceAndComments()
    {
        int c = get();
        for (;;)
        {
            if (c == '#')
            {
                while (c != EOF && c != '\n' && c != '\r') c = get();
            }
            else if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f')
            {
                c = get();
            }
            else
            {
                return c;
            }
        }
    }

    static constexpr std::size_t kMaxHeaderBytes = 64 * 1024;
    const std::string& m_path;
    std::ifstream& m_f;
    std::size_t m_count = 0;
};

ImageHeader readPnm(const std::string& path, std::ifstream& f, char kind)
{
    f.clear();
    f.seekg(2);
    PnmTokenizer tok(path, f);
    ImageHeader h;
    h.format = ImageFormat::Pnm;
    h.width = tok.number("width");
    h.height = tok.number("height");
    // PBM (P1, P4) has no maxval: its samples are bits.
    const bool is_bitmap = kind == '1' || kind == '4';
    const std::uint64_t maxval = is_bitmap ? 1 : tok.number("maxval");
    if (h.width == 0 || h.height == 0)
        fail(path, "invalid Netpbm header (declares " + sizeText(h.width, h.height) + " pixels)");
    if (maxval < 1 || maxval > 65535)
        fail(path,
             "invalid Netpbm header (maxval " + std::to_string(maxval) + " outside 1..65535)");
    h.max_value = is_bitmap ? 0 : static_cast<std::uint32_t>(maxval);
    return h;
}

// BMP: "BM", a 14-byte file header, then the DIB header whose size tells its layout:
// 12 bytes (OS/2 BITMAPCOREHEADER) has 16-bit sizes, all later ones signed 32-bit sizes
// (a negative height means rows stored top-down).
ImageHeader readBmp(const std::string& path, std::ifstream& f)
{
    std::array<unsigned char, 26> b{};
    const std::size_t n = readPrefix(f, b);
    if (n < 18) fail(path, "truncated BMP header");
    const std::uint32_t dib_size = le32(b.data() + 14);
    ImageHeader h;
    h.format = ImageFormat::Bmp;
    if (dib_size == 12)
    {
        if (n < 22) fail(path, "truncated BMP header");
        h.width = le16(b.data() + 18);
        h.height = le16(b.data() + 20);
    }
    else if (dib_size >= 16)
    {
        if (n < 26) fail(path, "truncated BMP header");
        const auto w = static_cast<std::int32_t>(le32(b.data() + 18));
        const auto ht = static_cast<std::int32_t>(le32(b.data() + 22));
        if (w <= 0) fail(path, "invalid BMP header (declares width " + std::to_string(w) + ")");
        h.width = static_cast<std::uint64_t>(w);
        // int64 first: the magnitude of INT32_MIN does not fit an int32.
        const std::int64_t ht64 = ht;
        h.height = static_cast<std::uint64_t>(ht64 < 0 ? -ht64 : ht64);
    }
    else
    {
        fail(path, "invalid BMP header (DIB header size " + std::to_string(dib_size) + " bytes)");
    }
    if (h.width == 0 || h.height == 0)
        fail(path, "invalid BMP header (declares " + sizeText(h.width, h.height) + " pixels)");
    return h;
}

// JPEG: a sequence of marker segments (0xFF, marker, big-endian length that counts itself);
// the frame header (SOFn) holds precision, height, width. EXIF and other APPn segments may
// come first and be large, so walk the segments instead of reading a fixed prefix.
ImageHeader readJpeg(const std::string& path, std::ifstream& f)
{
    f.clear();
    f.seekg(2);
    for (;;)
    {
        int c = f.get();
        if (c == EOF) fail(path, "truncated JPEG (no frame header)");
        if (c != 0xFF)
            fail(path, "invalid JPEG (marker expected at byte " +
                           std::to_string(static_cast<long long>(f.tellg()) - 1) + ")");
        // Any number of 0xFF fill bytes may precede a marker.
        do
        {
            c = f.get();
        } while (c == 0xFF);
        if (c == EOF) fail(path, "truncated JPEG (no frame header)");
        const int marker = c;
        // Stand-alone markers carry no length.
        if (marker == 0xD8 || marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) continue;
        if (marker == 0xD9 || marker == 0xDA)
            fail(path, "invalid JPEG (image data before any frame header)");
        std::array<unsigned char, 2> len_bytes{};
        f.read(reinterpret_cast<char*>(len_bytes.data()), 2);
        if (f.gcount() != 2) fail(path, "truncated JPEG (no frame header)");
        const std::uint32_t len = be16(len_bytes.data());
        if (len < 2) fail(path, "invalid JPEG (segment length " + std::to_string(len) + ")");
        // SOF0..SOF15, except DHT (C4), JPG (C8) and DAC (CC) which share the range.
        const bool is_sof =
            marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
        if (is_sof)
        {
            std::array<unsigned char, 5> sof{};
            f.read(reinterpret_cast<char*>(sof.data()), 5);
            if (f.gcount() != 5) fail(path, "truncated JPEG frame header");
            ImageHeader h;
            h.format = ImageFormat::Jpeg;
            h.height = be16(sof.data() + 1);
            h.width = be16(sof.data() + 3);
            // Height 0 means "defined later by a DNL marker", which OpenCV does not support.
            if (h.width == 0 || h.height == 0)
                fail(path, "invalid JPEG frame header (declares " + sizeText(h.width, h.height) +
                               " pixels)");
            return h;
        }
        f.seekg(static_cast<std::streamoff>(len) - 2, std::ios::cur);
        if (!f) fail(path, "truncated JPEG (no frame header)");
    }
}

}  // namespace

const char* imageFormatName(ImageFormat format)
{
    switch (format)
    {
        case ImageFormat::Png:
            return "PNG";
        case ImageFormat::Pnm:
            return "PGM/PPM/PBM";
        case ImageFormat::Bmp:
            return "BMP";
        case ImageFormat::Jpeg:
            return "JPEG";
    }
    return "image";
}

ImageHeader readImageHeader(const std::string& path)
{
    std::ifstream f(path, std::ios::binary);
    if (!f) fail(path, std::string("cannot be opened (") + std::strerror(errno) + ")");

    std::array<unsigned char, 8> magic{};
    const std::size_t n = readPrefix(f, magic);
    if (n == 0) fail(path, "is empty");

    static const unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    // A file cut inside the signature is still recognisably a PNG: say "truncated".
    if (std::memcmp(magic.data(), kPngSignature, n < 8 ? n : 8) == 0 && n >= 4)
    {
        if (n < 8) fail(path, "truncated PNG header");
        return readPng(path, f);
    }
    if (n >= 2 && magic[0] == 'P' && magic[1] >= '1' && magic[1] <= '6')
        return readPnm(path, f, static_cast<char>(magic[1]));
    if (n >= 2 && magic[0] == 'B' && magic[1] == 'M') return readBmp(path, f);
    if (n >= 3 && magic[0] == 0xFF && magic[1] == 0xD8 && magic[2] == 0xFF)
        return readJpeg(path, f);

    fail(path, "is not a PNG, PGM/PPM/PBM, BMP or JPEG image (unrecognised content)");
}

}  // namespace mrpt_topoeval::internal
