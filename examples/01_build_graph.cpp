/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Example 1: the Topology Graph of a map file (paper II), written as JSON.
//   01_build_graph MAP [OUT.json]     MAP: ROS .yaml, image, .gridmap[.gz], .simplemap[.gz]
#include <mrpt_topoeval/topoeval.h>

#include <iostream>

int main(int argc, char** argv)
{
    using namespace mrpt_topoeval;
    if (argc < 2)
    {
        std::cerr << "usage: 01_build_graph MAP [OUT.json]\n";
        return 2;
    }
    try
    {
        const LoadedMap map = loadMap(argv[1]);
        GraphBuildStats stats;
        const TopologyGraph graph = buildTopologyGraph(map.grid, GraphBuilderParameters{}, &stats);
        std::cout << map.file << " (" << map.format << "): " << graph.vertices.size()
                  << " vertices, " << graph.edges.size() << " edges\n";
        if (argc > 2) writeFileAtomic(argv[2], graphToJson(graph, &stats), /*overwrite=*/true);
        return 0;
    }
    catch (const std::exception& e)
    {
        std::cerr << "01_build_graph: " << e.what() << "\n";
        return 1;
    }
}
