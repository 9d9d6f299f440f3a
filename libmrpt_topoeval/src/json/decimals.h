/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// The fixed precisions of every JSON document the library writes, so equal results give equal
// bytes and the files stay readable.

namespace mrpt_topoeval::internal
{
/** Decimals of similarities in [0, 1] (finer than any threshold a user would set). */
constexpr int kSimilarityDecimals = 4;

/** Decimals of distances in metres: 0.1 mm, far below any cell size. */
constexpr int kMetreDecimals = 4;

/** Decimals of angles in degrees: 0.001 degree. */
constexpr int kDegreeDecimals = 3;

}  // namespace mrpt_topoeval::internal
