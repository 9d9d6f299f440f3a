/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// [MapLoad]: every key once (common/parameter_table.h); units and reasons in MapLoadOptions.h.

#include <mrpt_topoeval/maps/MapLoadOptions.h>

#include "common/parameter_table.h"

namespace mrpt_topoeval
{
TOPOEVAL_PARAMETER_TABLE(
    MapLoadOptions, NumberText::Shortest,
    real(TOPOEVAL_KEY(resolution_m), "m/cell",
         "cell size of plain images and of rendered .simplemap files", above(0)),
    real(TOPOEVAL_KEY(occupied_thresh), "probability",
         "plain images: a pixel is occupied if (255-grey)/255 > this", atLeast(0).atMost(1)),
    real(TOPOEVAL_KEY(free_thresh), "probability",
         "plain images: a pixel is free if (255-grey)/255 < this", atLeast(0).atMost(1)),
    // Equal thresholds would leave no unknown band, larger free would make cells both.
    relation(
        &P::free_thresh,
        [](const P& p)
        { return "free_thresh < occupied_thresh (" + shortestNumber(p.occupied_thresh) + ")"; },
        [](const P& p) { return p.free_thresh < p.occupied_thresh; }),
    word(TOPOEVAL_KEY(grey_between_thresholds), {"auto", "unknown", "probability"},
         "images without a ROS mode: pixels between the thresholds are unknown, or keep "
         "their probability (auto: when >4 such greys)"),
    integer(TOPOEVAL_KEY(trinary_unknown_grey), "grey 0-254",
            "ROS trinary maps of map_saver's greys only: this grey is unknown even if "
            "free_thresh says free (nav2 Humble wrote 0.25); -1 = off",
            atLeast(-1).atMost(254)),
    count(TOPOEVAL_KEY(max_cells), "cells",
          "largest map accepted (width x height), checked before decoding", above(0)))

}  // namespace mrpt_topoeval
