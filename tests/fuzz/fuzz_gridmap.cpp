/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// loadMap() on an MRPT serialized grid: `.gridmap.gz` when the bytes start with the gzip magic
// (MRPT's stream reads both, the name is what users give), `.gridmap` otherwise.

#include <mrpt_topoeval/maps/load_map.h>

#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace mrpt_topoeval;
    const bool gz = size >= 2 && data[0] == 0x1f && data[1] == 0x8b;
    const std::string path = fuzz::writeFile(gz ? "map.gridmap.gz" : "map.gridmap", data, size);
    MapLoadOptions opts;
    opts.max_cells = 1'000'000;  // the stored limits are checked before the cells are read
    fuzz::expectOnlyInputErrors([&] { loadMap(path, opts); });
    return 0;
}
