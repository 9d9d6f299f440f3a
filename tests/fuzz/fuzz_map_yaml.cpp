/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// loadMap() on a ROS map_server YAML and its image. The input is the YAML text, then a line
// "#IMAGE", then the image bytes, which are written as image.pgm, image.png, image.bmp and
// image.jpg next to the YAML: the YAML's `image:` key decides which one is decoded. Without
// the separator the whole input is the YAML.

#include <mrpt_topoeval/maps/load_map.h>

#include <algorithm>
#include <cstring>

#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace mrpt_topoeval;
    static const char kSep[] = "\n#IMAGE\n";
    const std::uint8_t* end = data + size;
    const std::uint8_t* sep = std::search(data, end, kSep, kSep + std::strlen(kSep));
    const std::uint8_t* image = sep == end ? end : sep + std::strlen(kSep);
    const std::size_t image_size = static_cast<std::size_t>(end - image);
    for (const char* name : {"image.pgm", "image.png", "image.bmp", "image.jpg"})
        fuzz::writeFile(name, image, image_size);
    const std::string yaml =
        fuzz::writeFile("map.yaml", data, static_cast<std::size_t>(sep - data));
    MapLoadOptions opts;
    opts.max_cells = 1'000'000;  // as in fuzz_image: keep each run in milliseconds
    fuzz::expectOnlyInputErrors([&] { loadMap(yaml, opts); });
    return 0;
}
