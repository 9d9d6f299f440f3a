/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <cstdint>
#include <string>

namespace mrpt_topoeval::internal
{
/** Image containers the map loader reads (OpenCV decodes them; we only read their headers). */
enum class ImageFormat
{
    Png,
    Pnm,  //!< Netpbm: PBM / PGM / PPM, plain (P1-P3) or raw (P4-P6).
    Bmp,
    Jpeg
};

/** What an image file declares about itself, read without decoding a single pixel. */
struct ImageHeader
{
    ImageFormat format = ImageFormat::Png;
    std::uint64_t width = 0;   //!< Pixels per row, as declared.
    std::uint64_t height = 0;  //!< Rows, as declared (absolute value for bottom-up BMPs).
    /** PGM / PPM only: the declared white level (`maxval`). OpenCV returns their samples
     * unscaled, so grey levels must be divided by this, not by 255 or 65535. 0 for the other
     * formats, whose decoded samples span their whole bit depth (OpenCV expands PBM bits to
     * 0 / 255). */
    std::uint32_t max_value = 0;
};

/** Short name of a format for messages ("PNG", "PGM/PPM", ...). */
const char* imageFormatName(ImageFormat format);

/** Reads the dimensions declared by a PNG, Netpbm (P1-P6), BMP or JPEG file from its first
 * bytes, so that a file declaring an absurd size can be refused before a decoder allocates
 * memory for it. The format is recognised by content, not by file name.
 *
 * \throws InputError `"<path>: ..."` (one line) when the file cannot be opened, is not one of
 *         these formats, or its header is truncated or invalid (zero or negative sizes, a
 *         Netpbm maxval outside 1..65535, a JPEG without a frame header). */
ImageHeader readImageHeader(const std::string& path);

}  // namespace mrpt_topoeval::internal
