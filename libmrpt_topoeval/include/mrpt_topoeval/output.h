/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <mrpt/img/CImage.h>

#include <string>
#include <string_view>

namespace mrpt_topoeval
{
/** Writes `bytes` to `path` through a temporary file in the same folder and a rename, so a
 * reader never sees a half-written file. Refuses to replace an existing file unless
 * `overwrite` (nothing a user produced is lost).
 * \throws OutputError naming the file and the reason. */
void writeFileAtomic(const std::string& path, const std::string& bytes, bool overwrite);

/** Encodes an image as PNG and writes it with writeFileAtomic(). \throws OutputError */
void writePngAtomic(const std::string& path, const mrpt::img::CImage& img, bool overwrite);

}  // namespace mrpt_topoeval
