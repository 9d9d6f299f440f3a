/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// loadMap() on a plain image: the first byte picks the format (by file name, as loadMap
// does), the rest is the file. Exercises our header checks (max_cells before decoding) and the
// image decoders as we call them.

#include <mrpt_topoeval/maps/load_map.h>

#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace mrpt_topoeval;
    if (size < 1) return 0;
    static const char* const kNames[] = {"map.png", "map.pgm", "map.bmp", "map.jpg"};
    const std::string path = fuzz::writeFile(kNames[data[0] % 4], data + 1, size - 1);
    MapLoadOptions opts;
    // Small enough that a map the headers allow decodes in milliseconds: the size check is
    // what is under test, not the decoders' speed on 10^8 pixels.
    opts.max_cells = 1'000'000;
    fuzz::expectOnlyInputErrors([&] { loadMap(path, opts); });
    return 0;
}
