/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once
// The validation corpus (doc/validation.md): what is true about a map against its ground truth,
// established without the matcher (by construction, known transforms, poses or keypoints).

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace mrpt_topoeval::validation
{
/** Where a point of the map's world frame lies in the ground truth's world frame [m], or
 * nothing where the map has no truth there (another building, a point outside every part). */
using TruthMapping = std::function<std::optional<Eigen::Vector2d>(const Eigen::Vector2d& p_map)>;

/** A rigid transform p_gt = R(yaw) p_map + t, for building truth mappings. */
struct Rigid2D
{
    double yaw_rad = 0.0;
    Eigen::Vector2d t_m{0.0, 0.0};
    Eigen::Vector2d apply(const Eigen::Vector2d& p) const;
    Rigid2D inverse() const;
    /** (*this) o (other): first other, then this. */
    Rigid2D compose(const Rigid2D& other) const;
};

/** `v` in fixed notation with `decimals` digits (for truth sources and notes). */
std::string fmt(double v, int decimals);

/** Everything the scorer needs to know about one map against its ground truth. */
struct Truth
{
    TruthMapping mapping;
    /** The other way, ground truth -> map, where the generator knows it (identity and warped
     * variants); used by the free-space check. Unset: not known. */
    TruthMapping forward;
    /** Human-readable origin of the truth ("by construction", "known transform (data README)",
     * "same frame", "keyframe poses", "12 hand-labelled keypoints, fit rmse 0.08 m"). */
    std::string source;
    /** Broken maps: the rigid part (index into part_yaw_deg) a map point belongs to, -1 for
     * none; unset for maps that are not broken by construction. */
    std::function<int(const Eigen::Vector2d& p_map)> part_of;
    /** A topology vertex's places in the ground truth, (part or -1, position), the most likely
     * first, when its position alone does not say (by the walls that make it, its Voronoi
     * sites within its clearance): broken maps give one place per part that put at least a
     * quarter of those walls there, then part_of(p_map) if not among them (a vertex on a seam
     * is made by two parts, and its place is then true by either); the keyframe truth asks
     * which scans drew those walls (one place, part -1; none when no keyframe places it).
     * Unset: part_of(p_map) (or -1) and mapping(p_map). */
    std::function<std::vector<std::pair<int, Eigen::Vector2d>>(const Eigen::Vector2d& p_map,
                                                               double clearance_m)>
        vertex_places;
    /** Rotation of each part, map -> ground truth [deg]; part 0 is the unbroken rest. */
    std::vector<double> part_yaw_deg;
    /** Breaks injected (brokenness the scorer expects); -1 when not known (real maps, SLAM). */
    int injected_breaks = -1;
    /** Truth check: an occupied map cell mapped into the ground truth must lie within this of a
     * ground-truth obstacle cell [m]. */
    double wall_tolerance_m = 0.10;
    /** Map points that were added on purpose and are no walls of the ground truth (speckles,
     * furniture): left out of the truth check. Unset = none. */
    std::function<bool(const Eigen::Vector2d& p_map)> is_clutter;
    /** True for a different building: no pair can be true, coverage must be ~0. */
    bool different_building = false;
    /** The variant keeps all of the ground truth's free space known (free, or under a wall or
     * clutter laid over it): set by identityTruth() and warpGrid(), so by every generated kind
     * but crops (which clear it), SLAM maps and other buildings. The truth check then also asks
     * that their free space be kept (a generator that lost it greyed out a broken map's turned
     * rooms until session 9). */
    bool keeps_free_space = false;
    /** Crops: where a ground-truth vertex at p_gt with that clearance lies against the part of
     * the map that was kept (the crop's rectangle): 2 kept, its clearance disc (where the walls
     * that make it lie) inside; 1 at the cut, its centre inside but its disc cut (it may or may
     * not survive); 0 cut away. So the share of ground-truth vertices kept is known without the
     * map's graph. Unset: the whole ground truth is kept. */
    std::function<int(const Eigen::Vector2d& p_gt, double clearance_m)> kept;
    /** Broken maps: the part that keeps a ground-truth vertex at p_gt with that clearance whole,
     * or -1: its clearance disc lies in that part, and no other part put a wall within it where
     * the part drew it in the map (walls win where parts overlap, so another part's wall there
     * changes the vertex). The walls that make such a vertex are all in the map, as in the
     * ground truth, whatever the map's graph makes of them. Unset: not a broken map. */
    std::function<int(const Eigen::Vector2d& p_gt, double clearance_m)> kept_part;
};
}  // namespace mrpt_topoeval::validation
