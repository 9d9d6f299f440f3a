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

/** `s` as a quoted JSON string, as in every JSON file the library writes: `"` and `\` escaped,
 * control characters as `\n` ... or `\u00XX`, valid UTF-8 unchanged, each byte of an invalid
 * sequence as U+FFFD (file names on Linux are arbitrary bytes; a JSON text must be UTF-8). */
std::string jsonQuote(std::string_view s);

}  // namespace mrpt_topoeval
