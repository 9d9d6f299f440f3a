/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <mrpt/config/CLoadableOptions.h>
#include <mrpt_topoeval/GraphMatch.h>
#include <mrpt_topoeval/TopologyGraph.h>
#include <mrpt_topoeval/similarity/vertex_similarity.h>

#include <string>

namespace mrpt_topoeval
{
/** Which matcher pairs the vertices (doc/matching.md). */
enum class MatchMethod
{
    /** Groups of pairs verified by local geometric consistency (distances between the
     * vertices of a group agree in both maps), found as maximum cliques of a pairwise
     * consistency graph and grown through graph neighbours. Tolerates local topology changes. */
    Consistent,
    /** The paper's (III-B): subgraph isomorphism by wavefront, then neighbour growing. */
    Paper
};

/** "consistent" / "paper". */
std::string toString(MatchMethod m);
/** Parses "consistent" / "paper". \throws InputError naming the value. */
MatchMethod matchMethodFromString(const std::string& s);

/** Parameters of the structural matcher (paper III-B), INI section `[GraphMatcher]`. Global
 * vertex positions are never used: robot maps have wrong global frames. The consistent method
 * compares only distances between vertices of one map with those of the other. */
struct GraphMatcherParameters : public mrpt::config::CLoadableOptions
{
    /** The INI section of these keys, named by validate() in its messages. */
    static constexpr const char* kIniSection = "GraphMatcher";

    MatchMethod method = MatchMethod::Consistent;

    // --- method = paper
    /** Two matched edges must agree in length within factor x the longer + allowance (paper:
     * "the length of the edges must coincide at least to a certain degree") [ratio]. */
    double edge_length_factor = 0.25;
    double edge_length_allowance_m = 0.75;  //!< [m]
    /** Matched edges at a vertex must leave it at angles (relative to the ring's other
     * edges) that differ by at most this [deg]. */
    double max_angle_difference_deg = 40.0;
    /** Pairs less similar than this are never assigned by the isomorphism [0..1]. */
    double min_isomorphism_similarity = 0.4;
    /** An isomorphism is accepted when it has at least this many vertices; on graphs too
     * small for that, at least min_isomorphism_share of the smaller graph's matchable vertices
     * (and never fewer than 3). Small isomorphisms are common between different buildings
     * made of the same corridors and rooms: 8 kept every such pair of our test maps apart [1]. */
    int min_isomorphism_vertices = 8;
    double min_isomorphism_share = 0.75;  //!< [ratio]
    /** Branches the wavefront may explore per seed pair before it takes the best branch
     * without exploring further (bounds recursion on repetitive maps) [1]. */
    int max_branches_per_seed = 64;
    /** Run neighbour growing after the isomorphisms (paper III-B end) [bool]. */
    bool neighbour_growing = true;
    /** Neighbour growing assigns a pair only if its similarity is at least this [0..1]. */
    double min_growing_similarity = 0.5;
    /** Neighbour growing's relaxed edge-length check: factor and allowance [ratio], [m]. */
    double growing_edge_length_factor = 0.5;
    double growing_edge_length_allowance_m = 2.0;

    // --- method = consistent (doc/matching.md, "Consistent groups")
    /** Candidate partners of each ground-truth vertex: its most similar map vertices, and the
     * map vertices for which it is among the most similar (a repeated corridor junction has
     * several look-alikes; the geometry chooses) [1]. */
    int candidates_per_vertex = 5;
    /** Candidates are at least this similar [0..1]. Low: geometry, not similarity, decides;
     * similarity only keeps the consistency graph small. */
    double min_candidate_similarity = 0.1;
    /** When no further group is found, the candidates are made once more with this many
     * most similar free partners per free vertex, and further groups are searched again
     * (back to candidates_per_vertex after each group found there). A part cut off at a
     * break changed its vertices' attributes at the cut (their edges end there), so its true
     * partners rank a few places down. A group found with the longer lists must also be
     * significant among them (max_false_alarms): longer lists hold more chance groups. At
     * most candidates_per_vertex: off (doc/matching.md, "A wider look at the leftovers") [1]. */
    int leftover_candidates_per_vertex = 10;
    /** When no first group is found among the candidates_per_vertex lists, it is sought once
     * more among leftover_candidates_per_vertex lists, with the pairs of the cliques refused
     * before asked again; it must pass every test of a first group, significance among the
     * longer lists included. In a hall's lattice, whose junctions all look alike, a break
     * changes the attributes of the vertices next to it and their true partners rank below
     * the first lists (doc/matching.md, "A wider look for the first group") [bool]. */
    bool first_group_wider_look = true;
    /** Candidate and grown pairs differ in degree by at most this: a small loop or an extra
     * dead end changes a junction's degree by one [1]. */
    int max_degree_difference = 1;
    /** Two pairs (g1, m1), (g2, m2) are consistent when |d(g1, g2) - d(m1, m2)| is at most
     * distance_tolerance_m + distance_tolerance_ratio x the longer distance +
     * clearance_tolerance_share x (clearance of g1 + clearance of g2). The absolute term
     * covers skeleton noise. A first group whose vertices lie within it of one line (RMS) is
     * refused: across the line it checks nothing (doc/matching.md, "A first group along one
     * line") [m]; */
    double distance_tolerance_m = 0.25;
    /** ... the relative term slow bending and scale errors of robot maps [ratio]; */
    double distance_tolerance_ratio = 0.03;
    /** ... the clearance term the position of a room's vertex, defined only up to its room's
     * medial-axis plateau (about its clearance) [ratio]. */
    double clearance_tolerance_share = 0.15;
    /** A group (maximum consistent set) is accepted when it has at least this many pairs;
     * smaller consistent sets occur by chance between unrelated places [1]. */
    int min_group_vertices = 5;
    /** On a graph too small for min_group_vertices (a plan of a few rooms), a group of at least
     * min_small_graph_group_share of the smaller graph's matchable vertices (and 3) is accepted
     * when its pairs' mean vertex similarity is at least this, or its walls agree and pin its
     * fit (min_part_wall_agreement, max_wall_pinning): three consistent distances alone are
     * common between unrelated places [0..1]. */
    double min_small_group_similarity = 0.7;
    /** ... a group needs this share of the smaller graph's matchable vertices (and 3), not the
     * paper's min_isomorphism_share: a robot map of a flat shows part of it (doors closed,
     * rooms not entered), and with 0.75 a layout of 6 vertices would need 5 of them. That
     * group is the best of every maximal clique of the candidates, each settled
     * (doc/matching.md, "A small graph") [ratio]. */
    double min_small_graph_group_share = 0.6;
    /** ... after keeping its biggest part linked in both graphs: two pairs are linked when
     * their ground-truth vertices are within this many edges of each other, and so are their
     * map vertices (2: one vertex may be missing or extra in between). Consistency by chance
     * scatters its pairs over the graphs [1]. */
    int support_hops = 2;
    /** ... and when its vertices span at least this far in the ground truth (a group of
     * vertices all within a few metres fixes no geometry) [m]. */
    double min_group_extent_m = 4.0;
    /** ... and when the rigid fit of its pairs has a mean squared error of at most this: a
     * group is one rigid part, as the evaluation's brokenness groups are (the paper's
     * SquaredErrorThreshold, the same 0.2 m^2 as [Quality] brokenness_max_squared_error_m2).
     * Each pair within its own tolerance is not enough: a chance group spreads its errors
     * to the limit of every pair's [m^2]. */
    double max_group_squared_error_m2 = 0.2;
    /** A further group (once a first one is accepted) whose pairs each lie within their
     * tolerance but whose fit's mean squared error is over max_group_squared_error_m2 loses
     * its pair placed worst against its tolerance, again while the error is over and it has
     * more pairs than it needs: the vertices of a column hall or an open room slide along the
     * medial axis between maps, and a true part's fit, pulled by one or two of them, was
     * refused whole (held-out corpus seeds 2-16: `column_hall_11004/broken_2`'s part 1, 6
     * pairs at 0.268 m^2). Not for the first group, which decides that the maps show one
     * place: refusing a chance clique whole keeps its pairs out of the next one (trimmed, a
     * first group lost a real building's broken map, `gazebo_office/broken_3`). false: a
     * further group over the limit is refused (doc/matching.md, "A further group trimmed to
     * one rigid part") [bool]. */
    bool trim_further_groups_to_rigid = true;
    /** Most groups (each one rigid part of the map: a broken map gives one per part) [1]. */
    int max_groups = 8;
    /** Branch-and-bound steps per clique search; when spent the best clique so far is taken
     * (bounds the time on dense consistency graphs; deterministic) [1]. */
    int max_clique_steps = 200000;
    /** The first group (the one that decides that the maps show one place) of at least
     * min_group_vertices pairs must be significant: the expected number of groups as big that
     * chance alone would make among the candidates (the number of false alarms of Desolneux,
     * Moisan and Morel's a contrario test: subsets times the consistency graph's density to the
     * power of the group's pair distances) at most this. 1 is the a contrario default (less
     * than one false detection expected); the corpus's false first groups between buildings of
     * one style had 0.7-9 (doc/matching.md) [expected count]. */
    double max_false_alarms = 1.0;
    /** A further group (another part of a broken map) is the best consensus of the candidates
     * still free: the transform of two linked, consistent pairs at least this far apart in the
     * ground truth, and the pairs it puts in place (near a break a clique mixes two parts, and
     * a fit of all is a compromise); 2 m keeps the rotation of two vertices known within
     * 0.25 m within about 7 degrees, under the 10 degrees of a small break [m]. */
    double min_consensus_baseline_m = 2.0;
    /** Once a group is accepted, a further group (a small part of a broken map) needs only
     * this many pairs when it bridges to an accepted group (part_bridge_ratio) and their mean
     * similarity is at least min_small_group_similarity: the 5 of the paper miss the parts of
     * a building cut in three or four [1]. */
    int min_part_group_vertices = 3;
    /** A further group is one linked piece of both graphs (support_hops), but a part's rigid
     * set of pairs can lie in two pieces: a room whose loop puts 5-6 edges between its two
     * ends, the unmatched vertices between them changed at the cut. Other linked pieces of at
     * least this many pairs join the biggest when the biggest holds as many pairs as a
     * further group needs (min_part_group_vertices), its own fit places each of them within
     * tolerance, the walls around the whole agree and pin it (min_part_wall_agreement,
     * max_wall_pinning) and the whole is an acceptable group (judged by its own size). 2, not
     * 1: two linked pairs are a fixed segment, one is any vertex the fit happens to place.
     * Not for the first group. 0: off (doc/matching.md) [1]. */
    int min_joined_piece_pairs = 2;
    /** A further group of at least min_scattered_part_pairs pairs none of whose linked pieces
     * is big enough (the vertices between a part's counterparts changed at its cut, so no two of
     * its pairs are within support_hops edges in both maps) is kept whole when it is significant
     * among the candidates as a first group must be (max_false_alarms), its walls agree and
     * pin its fit (min_part_wall_agreement, max_wall_pinning), and it is another part: its fit
     * misplaces at least half of every accepted group's pairs (a scattered set of an accepted
     * part's pairs is growing's to reach; its own fit puts them a few decimetres off). false:
     * such a group is refused (doc/matching.md, "A part in scattered pieces") [bool]. */
    bool scattered_part_groups = true;
    /** The fewest pairs of a scattered part (scattered_part_groups). Its significance among
     * the candidates decides, not its size: among the hundreds of candidates of a building a
     * part of 3-4 pairs is seldom significant, and when it is, it is a part (held-out corpus
     * seeds 2-16: with 4 instead of session 26's 5 (min_group_vertices), 6 broken cases more
     * exactly right, +22 true pairs, +2 false, near-twins and `different` unchanged; 3 gives
     * the same as 4). At least 3, the fewest a rigid fit checks (doc/matching.md, "A part in
     * scattered pieces") [1]. */
    int min_scattered_part_pairs = 3;
    /** The last look for further groups, once no other is found even with the wider lists
     * (leftover_candidates_per_vertex; with those off, on the first lists), each group found
     * there significant as in the wider look: two pairs whose map vertices lie in different
     * pieces (connected components) of the map's graph are linked when their ground-truth
     * vertices are (within support_hops edges). At a break the map's graph falls into pieces
     * that no edge joins (a corridor closed at the cut, a part laid over another's rooms and
     * cut by their walls); there the map cannot vouch for the link either way, and the ground
     * truth still does. Within one piece both graphs must link the vertices, as always. Not for
     * the first group, which decides that the maps show one place; only as the last look
     * because, asked of every further group, it also let groups mix two parts (held-out corpus
     * seeds 2-16: 73 true pairs more and 43 false; as the last look 45 and 10). false: both
     * graphs must always link (doc/matching.md, "A part cut into pieces of the map's graph")
     * [bool]. */
    bool link_across_map_pieces = true;
    /** A further group whose biggest linked piece is refused (a few pairs spanning less than
     * min_group_extent_m, or without a bridge) is kept whole when the scattered part's tests
     * accept it (scattered_part_groups: min_scattered_part_pairs, significant as a first
     * group must be, another part, its walls agree and pin its fit). The part's other pairs lie
     * more than support_hops edges away because the vertices between them changed at the cut.
     * false: the whole is asked only when no piece is big enough. Nothing with
     * scattered_part_groups = false (doc/matching.md, "A part in scattered pieces") [bool]. */
    bool scattered_part_when_piece_refused = true;
    /** When the maximum clique does not settle into a first group (on a broken map it often
     * mixes the parts: near a cut's pivot their distances agree) and its own consensus is no
     * group either, every maximal clique of the pool with at least min_group_vertices
     * candidates is settled, once per search (within max_clique_steps; not for a rival
     * placement given in advance), and the one that settles to the most pairs, then the most
     * similar, is the first group when its walls agree and pin its fit
     * (min_part_wall_agreement, max_wall_pinning; never with that test off) and it passes the
     * first group's tests (significance, walls, line). It is not chosen by its walls: among
     * hundreds of cliques the best walls of a chance one reach 0.52-0.66 (held-out corpus
     * seeds 2-16, `different` and near-twins). false: the maximum clique's pairs leave the
     * pool and the next maximum clique is tried (doc/matching.md, "A first group among the
     * maximal cliques") [bool]. */
    bool first_group_from_maximal_cliques = true;
    /** With first_group_from_maximal_cliques, the maximal cliques are asked also when the
     * maximum clique settles but its group fails a first group's tests (on a broken map a
     * clique of two parts' pairs settles to one part's corridor, refused as a group along one
     * line, and its pairs leave the pool with the other part's), and their groups are tried in
     * turn, best first, until one passes every test (each chance group's walls fail, as the
     * best one's do). false: only the best group, and only when the maximum clique does not
     * settle (session 31; doc/matching.md, "Maximal cliques in turn") [bool]. */
    bool first_group_maximal_cliques_in_turn = true;
    /** The share of the walls that must agree around a first group found among the maximal
     * cliques when it is not the one group session 31's rule asks (the best group after a
     * maximum clique that did not settle, which needs min_part_wall_agreement): every further
     * group tried is one more chance for a chance group's walls to agree. Held-out corpus seeds
     * 2-16 and 23-24: true first groups found in turn 0.90-0.99, a near-twin's chance group 0.71
     * (doc/matching.md, "Maximal cliques in turn") [0..1]. */
    double first_group_in_turn_min_wall_agreement = 0.85;
    /** A group is one rigid part, and so is every pair of it: the walls around a pair, aligned
     * by their own ICP from the group's fit, turn as its part turns. A pair whose walls turn
     * more than this from the turn most of the group's pairs' walls agree on is another part's,
     * placed within tolerance only because it lies near the pivot of the turn between the two
     * (at a cut, a turn of 10-30 degrees moves the vertices next to it by a few decimetres). A
     * settled group loses such pairs and is settled again, when what is left is still a group
     * (a small part's pair at its cut may be its bridge). Only a pair whose walls agree under
     * their own ICP (min_part_wall_agreement) has a turn; a pair without one (a vertex on the
     * seam of two parts has half of each's walls) stays when the fit of the pairs whose turns
     * agree (3 or more) places it within its tolerance. Measured on held-out
     * corpus seeds 5, 8 and 10 (each accepted group's pairs against the generator's parts,
     * which turn at least 10 degrees apart), against the median of the group's pairs' turns:
     * of 4 195 pairs of the group's own part 2 turn more than 6 degrees from it and 1 more than
     * 8; of 59 pairs of another part 49 turn more than 8. 0: off (doc/matching.md, "A pair whose
     * walls turn away") [deg]. */
    double max_pair_turn_deg = 8.0;
    /** A small further group (fewer than min_group_vertices pairs) whose pairs the links do
     * not join into one piece big enough (support_hops: the vertices between a small part's
     * pairs changed at the cut, or lie more edges apart than the links reach) is kept whole
     * when its walls agree under its fit on at least this share and pin it (max_wall_pinning),
     * and it is acceptable as every small further group must be (a bridge to an accepted
     * group, similarity or walls). Not in the wider look nor across the map's pieces, where a
     * group must be significant. Measured on held-out corpus seeds 2-16: of such groups true
     * parts' walls agreed on 0.71-1.00 (most 0.9 and more), the near-twins' chance groups on
     * 0.70-0.98 (most under 0.9), and a symmetric floor plan's wing placed by its symmetry on
     * 0.86. 0: off (doc/matching.md, "A small part whose pairs the links do not join")
     * [ratio]. */
    double min_unlinked_part_wall_agreement = 0.9;
    /** A further group kept whole though its linked pieces are too small (a scattered part,
     * scattered_part_groups, or an unlinked small part, min_unlinked_part_wall_agreement),
     * whose walls do not agree under its fit or do not pin it, is asked again under the walls'
     * own alignment: their ICP, started from the group's fit, when that alignment still places
     * every pair within its tolerance. Such a part's fit is made of a few vertices that slid
     * at the cut (a few decimetres), and its walls then agree with a shifted copy of
     * themselves better than with their place; their own alignment puts them there. Not asked
     * of the other wall tests (a small group's bridge, joined pieces): asked there too it
     * found more parts on held-out seeds, but let shifted placements of rooms alike in
     * (doc/matching.md, "The walls under their own alignment"). false: the group's fit only
     * [bool]. */
    bool walls_under_own_alignment = true;
    /** ... asked only when at least this share of the walls agree under the group's fit: the
     * ICP corrects a fit a few decimetres off, not a wrong placement (most of whose walls
     * disagree), and each ask costs an ICP of a thousand wall points or so. On held-out corpus
     * seeds 2-16 every group that passed under its walls' own alignment had 0.52 or more
     * under its fit, while 96 % of the groups asked had under 0.5 (none of the Intel pair's
     * passed; asked of all it cost 18 ms of its 75). 0.5 is also what a small first group's
     * walls must agree on (min_first_group_wall_agreement) [0..1]. */
    double own_alignment_min_wall_agreement = 0.5;
    /** A further group next to an accepted one in the ground truth (support_hops) must have a
     * bridge: one such neighbour pair whose map distance equals its ground-truth distance
     * within distance_tolerance_m + clearance share + this x the distance (a turn of up to 30
     * degrees at the cut changes it by about half). Rejects chance groups that sit next to an
     * accepted group in the ground truth but elsewhere in the map [ratio]. */
    double part_bridge_ratio = 0.5;
    /** A further group of at least min_group_vertices pairs whose neighbour pairs all changed
     * their distance (the turn moved them: they lie far from its pivot) still meets the
     * accepted groups when the pivot of the turn between its fit and an accepted group's fit
     * (where both place the map alike: where the robot crossed the break) lies within this of
     * a ground-truth vertex of each. A chance group's turn has its pivot anywhere, a lattice's
     * shift has none. 8 m: the low end of the range that gives the same corpus results (8 to
     * 15 m; 6 m misses a part, doc/matching.md). A small group (fewer than min_group_vertices)
     * that bridges so must also pass the wall test below (min_part_wall_agreement,
     * max_wall_pinning) [m]. */
    double part_pivot_distance_m = 8.0;
    /** A small further group none of whose ground-truth vertices lies within support_hops
     * edges of an accepted group's (the parts between them unmatched: a building broken three
     * times, its middle part changed most at its two cuts) has no neighbour pair to bridge by,
     * and the pivot of its turn against a part it does not touch lies anywhere. It is accepted
     * when it is as similar as a small group must be (min_small_group_similarity) and the
     * walls around it agree under its fit and pin it (min_part_wall_agreement,
     * max_wall_pinning): the tests a small graph's group and a pair grown without links pass.
     * A group that has a neighbour pair whose distance disagrees stays refused (a hall's
     * lattice). false: such a group needs the pivot (doc/matching.md, "A part that touches no
     * matched part") [bool]. */
    bool isolated_part_bridge = true;
    /** A further group as big as a first group must be (min_group_vertices pairs, fewer on a
     * small graph) that has a ground-truth neighbour pair whose distance the turn changed, and
     * whose pivot lies far from the accepted groups (neither bridge above), is accepted when the
     * walls around it agree under its fit and pin it (min_part_wall_agreement,
     * max_wall_pinning), as a small part's must. Two parts that both turned, each about its
     * own pivot, turn against each other about a point that may lie far from both: the parts
     * of a building cut three times. A chance group in a hall's lattice that sits next to the
     * true group keeps its walls' test to pass. false (or min_part_wall_agreement = 0): such a
     * group is refused (doc/matching.md, "A part whose neighbour moved") [bool]. */
    bool part_wall_bridge = true;
    /** A further group (after the first) whose walls do not agree under its fit and pin it
     * (min_part_wall_agreement, max_wall_pinning) is refused when its pairs' mean similarity
     * is below this. Its distances alone vouch for it, and distances repeat: a hall's lattice
     * of columns, a building symmetric under a turn. 0.5, the similarity neighbour growing
     * asks of a pair it assigns on topology alone (min_growing_similarity): a group at least
     * that alike is supported by its attributes. On corpus seeds 1-5 the true further groups
     * whose walls disagree have mean similarity 0.53 and more, the two chance groups of that
     * kind 0.33 and 0.49. The median of the candidates' similarity, the chance level of each
     * pair of maps, was measured too and refuses a true part of a building whose rooms are all
     * alike (candidates' median 0.99; doc/matching.md, "A group that only distances vouch
     * for"). With min_part_wall_agreement = 0, or maps without walls, no group's walls
     * agree: every further group less similar than this is refused. 0 turns the rule off
     * [0..1]. */
    double min_unconfirmed_group_similarity = 0.5;
    /** A further group smaller than min_group_vertices and less similar than
     * min_small_group_similarity (a part whose vertices' attributes changed at the cut: its
     * junctions lost or gained the edges across it) is still accepted when the obstacles
     * around it agree under its rigid fit: at least this share of the wall points around its
     * vertices lie on the other map's walls, counted from each map, the smaller share taken.
     * 0.6 and 0.7 give the same corpus, 0.5 admits a chance group in a column hall's lattice,
     * 0.8 finds no part (doc/matching.md); 0 turns the rule off [0..1]. The same test lets
     * growing without links take a pair less similar than min_small_group_similarity (down to
     * min_consistent_growing_similarity): a room off a furnished hall, whose dead end's
     * junction the desks changed (doc/matching.md, step 4). */
    double min_part_wall_agreement = 0.7;
    /** ... and when the walls pin the fit: moved by twice the wall tolerance in any of 8
     * directions, the fit keeps at most this share of its agreement. A straight corridor's
     * walls fit themselves anywhere along it (and turned by 180 degrees): 1.01-1.06 for the
     * chance groups of the corpus's corridors, 0.79-0.87 for the true parts found [ratio]. */
    double max_wall_pinning = 0.9;
    /** A first group of fewer than first_group_wall_check_pairs pairs, significant by the a
     * contrario test, is still refused unless the obstacles around it agree under its rigid
     * fit: at least this share of the wall points around its vertices on the other map's
     * walls (as for a small part, min_part_wall_agreement). Measured on held-out corpus seeds
     * 2 and 3 (doc/matching.md, "The walls of a small first group"): the chance first groups
     * between different buildings of one style and between near-twins had shares 0.28-0.49
     * (two 0.69-0.70), the true first groups of fewer than 10 pairs 0.51 and more. The pinning test
     * is not asked here: a true first group of a broken or SLAM map is often a few decimetres
     * off its best fit, and moved it agrees more (pinning 0.99-1.20). 0 turns it off [0..1]. */
    double min_first_group_wall_agreement = 0.5;
    /** ... the size from which a significant first group is trusted without its walls: the
     * chance first groups of the corpus had 5-6 pairs (near-twins up to 18, refused by their
     * similarity or significance), and big true groups of distorted SLAM maps have wall
     * shares down to 0.35 (a column hall's walls are its columns) [1]. */
    int first_group_wall_check_pairs = 10;
    /** A significant first group of any size is refused when at least this share of its pairs
     * (those with walls around both vertices) have walls that disagree where they are: each
     * pair's walls (min_part_wall_agreement), under the group's fit or, failing that, under an
     * ICP of that pair's own walls from it. A drifted SLAM map's big first group has walls that
     * disagree under one rigid fit, which first_group_wall_check_pairs therefore does not ask
     * of it, but each pair's walls agree once aligned where the pair is (true first groups of
     * corpus seeds 1 and 7: 0.40 of their pairs disagreeing at most, a SLAM map 0.33); two
     * buildings of one style whose chance group holds 10 pairs, two column halls of one bay,
     * 1.00, and a 6-pair chance group of two multi-wing buildings 0.50 (doc/matching.md, "The
     * walls of each pair of a first group"). 0 turns it off [0..1]. */
    double first_group_disagreeing_pair_share = 0.5;
    /** ... and a further group (a broken map's other part) likewise, by the same test: a wing
     * of a building symmetric under a turn, placed by its symmetry (held-out
     * multi_wing_8004/broken_2: 5 pairs, mean similarity 0.62, turned 184 degrees from the
     * part's truth) keeps its distances and its vertices' attributes, not its walls
     * (doc/matching.md, "The walls of each pair of a further group"). 0 turns it off [0..1]. */
    double further_group_disagreeing_pair_share = 0.5;
    /** A further group whose walls agree on less than this share of their length under its
     * fit, and under their own alignment (walls_under_own_alignment) too, is refused: its
     * vertices agree, its walls do not. A column hall's lattice repeats under a quarter turn,
     * and five junctions paired a quarter turn off keep their distances and enough similarity
     * (fresh corpus seed 26: walls 0.16). Asked only where both maps have walls around the
     * group; 0: off (doc/matching.md, "A further group whose walls disagree") [0..1]. */
    double further_group_min_wall_agreement = 0.3;
    /** Rival placements of the first group searched and, each as acceptable as a first group
     * (the same tests), played out to a whole match; the match whose pairs are the most similar
     * in sum is kept. In a building symmetric under a turn or a mirror the maximum clique is
     * one of several placements of its part, and the one found first is chance (a pentagonal
     * floor plan, symmetric under turns of 72 degrees, has 4 rivals; doc/matching.md, "Rival
     * placements"). Each rival played out costs one more match. 0 turns it off [count]. */
    int max_rival_placements = 4;
    /** ... a rival is played out only when it keeps at least this share of the first group's
     * pairs (before and after its fit is settled): a much smaller one is decided by size, as a
     * maximum clique is. As in Lowe's ratio test (2004), whose 0.8 this is: the rivals of
     * symmetric buildings in the corpus kept 0.85-1, the chance ones 0.16-0.6 (two of 6 pairs, 0.83
     * and 1, are played out and lose) and a mirrored wing of a broken map 0.67, which played out
     * wins by one grown pair's similarity and is false (held-out seed 2, doc/matching.md) [ratio].
     */
    double min_rival_size_ratio = 0.8;
    /** The wall points around a group: those within each vertex's clearance plus this [m]. */
    double wall_margin_m = 1.0;
    /** A wall point agrees when the other map has one within this, or within 1.5 cells of
     * the coarser map (the validation's truth check's tolerance) [m]. */
    double wall_tolerance_m = 0.15;
    /** Growing: an unmatched vertex near a group is paired where the rigid fit of the group's
     * pairs within this radius of it predicts its partner [m]; */
    double growing_radius_m = 12.0;
    /** ... the prediction must fall within position_tolerance_m + clearance_tolerance_share x
     * clearance of the vertex [m]; */
    double position_tolerance_m = 0.4;
    /** ... and the pair must be at least this similar [0..1]; */
    double min_consistent_growing_similarity = 0.2;
    /** ... and at least this share of the walls around it (wall_margin_m, wall_tolerance_m)
     * must agree under that fit, from both maps, when both maps have walls: a vertex the fit
     * puts in place by chance, in a region the two maps draw differently (a bent map's room
     * the fit does not reach), has none (Intel: a pair 1.47 m off with a share of 0) [0..1]. */
    double min_grown_wall_agreement = 0.1;

    // --- the clutter pass (evaluate(); doc/matching.md, "The clutter pass")
    /** After a first match, the map's free-standing obstacles that the ground truth does not
     * have where the match puts them (furniture a floor plan lacks) are made free and the map's
     * graph is built and matched again; that match is kept when it pairs more vertices, and the
     * pass repeats (a grown match reaches further islands) at most this many times. Every desk
     * or shelf in a room or hall puts a loop around itself into the map's graph, and the plan's
     * junctions there then have no similar partner. Only with method = consistent (method =
     * paper keeps the paper's pipeline). 0 turns it off [count]. */
    int clutter_passes = 3;
    /** ... an island (8-connected non-free cells surrounded by free space) wider than this
     * (smallest enclosing circle) is building structure, never clutter: furniture is at most a
     * desk row or a shelf (the validation corpus's desks 0.6-1.6 m long, its shelves 1-2 m, a
     * warehouse's pallets 0.8-1.2 m; racks and free-standing walls are longer) [m]; */
    double clutter_max_size_m = 3.0;
    /** ... and only islands within this of a matched map vertex are judged: farther, in a
     * broken map's unmatched part, the match's alignments say little. A furnished hall's match
     * grows only as far as the desks near its pairs are freed, pass by pass; measured on the
     * validation corpus's furnished maps (furniture recall, every pair true at each): 5 m 0.956,
     * 8 m 0.989, 12 m 0.991, with nothing else changed by more than a false pair, so 8 m
     * (doc/matching.md §2c) [m]; */
    double clutter_reach_m = 8.0;
    /** ... an island is the ground truth's (a column, a pallet the plan draws) when at least
     * clutter_min_wall_share of its border cells lie within this of a ground-truth wall point
     * under one of the match's alignments (relative accuracy's, each brokenness group's): twice
     * the matcher's wall_tolerance_m, as an alignment of a whole SLAM map is off by a cell or
     * two at its edges where a pair's walls are not [m]; */
    double clutter_wall_tolerance_m = 0.3;
    /** ... the share of the island's border cells that must lie there: half, so that a desk
     * pushed against a wall (its side along the wall on the plan's wall) is clutter, and a
     * column a cell or two off is not [ratio]. */
    double clutter_min_wall_share = 0.5;
    /** ... and the pass runs only when, on its first round, at least this share of the islands
     * judged are clutter: the map is furnished where its ground truth is not. A ground truth
     * drawn from a robot map of the same place holds the same furniture, and the few islands it
     * lacks are noise that a rebuild and a second match (as long as the first) would not repay.
     * Measured: the corpus's furnished maps 0.54-1.0 of their islands, the Intel ICP-SLAM map
     * against the Intel reference 0.07 (7 of 99) [ratio]. */
    double clutter_min_share = 0.25;
    /** ... and when the map's own match pairs fewer than 3 vertices, which gives no alignment to
     * judge its islands by, the pass takes its first alignments from a match of the map with
     * every island from min_island_size_m to clutter_max_size_m freed, unjudged (a column the
     * ground truth draws too): a map furnished everywhere (a warehouse's pallets around every
     * junction) can match nothing as it is. Only its islands are then judged as above, and its
     * match is kept only when it pairs more vertices than the map's own: the unjudged map is
     * never the one scored. Measured on the held-out warehouse style, seeds 1-10 (doc/matching.md
     * §2c) [bool]. */
    bool clutter_start_without_islands = true;
    /** The scale pass (doc/matching.md, "A map at another scale"): a floor plan whose YAML
     * gives a wrong resolution, or a map whose odometry misjudged distances, has every distance
     * off by one factor; distance_tolerance_ratio forgives 3 % of it, and beyond that only
     * groups a few metres wide stay consistent (a map 5 % too large fell into "broken" parts or
     * matched nothing). When the first match's rigid groups show the map's distances off by more
     * than this share of the ground truth's (and by scale_min_sigmas standard errors), the
     * map's graph is read at the ground truth's scale and matched again, at most twice, its
     * brokenness measured there (a map whose distances are all off by one factor is inaccurate,
     * not broken: accuracy and consistency still measure it as given), and the report gives the
     * factor (`map_scale`). 1 % is a third of the pairwise tolerance. 0 = off [ratio]. */
    double scale_min_error = 0.01;
    /** ... and by at least this many standard errors of the estimate (a small group's few
     * vertices, sliding along the medial axis, give a loose factor) [1]. */
    double scale_min_sigmas = 3.0;
    /** ... and the reading at the ground truth's scale is kept when its pairs fall into fewer
     * brokenness groups (a map off by one factor falls into more groups than it has parts; at
     * its scale they join) and it keeps at least this share of the pairs of the reading before
     * it: a pair at the edge of its tolerance may come or go with the factor (the Radish
     * Freiburg 079 reference 5 % too large: 75 pairs in 3 groups, then 74 in one). A reading
     * that joins no group was not the map's error (doc/matching.md) [ratio]. */
    double scale_min_pair_share = 0.9;
    /** The scale search (doc/matching.md, "A map at another scale"): a map whose every distance
     * is off by more than the pairwise tolerance forgives can match nothing at all, and then no
     * group shows its factor (4 of the 31 standard maps read 5 % too large; a floor plan whose
     * YAML gives a wrong resolution). When the match, after the clutter pass, pairs nothing, the
     * map's graph is read at the factors (1 + this)^-k and (1 + this)^k, k = 1 ..
     * scale_search_steps, nearest first; the reading with the most pairs at the first k that
     * pairs any is kept, the scale pass refines its factor from its groups, and the report gives
     * the factor (`map_scale`). 5 % is under twice distance_tolerance_ratio, so every factor
     * between two steps is within one tolerance of either. 0 = off [ratio]. */
    double scale_search_step = 0.05;
    /** ... this many steps each way: 2 reaches factors 0.907-1.103 [count]. */
    int scale_search_steps = 2;
    /** ... and a reading counts only when its biggest group holds this share of the smaller
     * graph's matchable vertices (and first_group_wall_check_pairs; its first group is also
     * held to max_false_alarms shared by the readings). A reading stands for the whole map at
     * another scale, which is one part or a few big ones there: the maps read 5 % too large
     * matched 97-100 % of their vertices in one group, the chance groups the search found
     * between near-twin buildings 11 of 80 [ratio]. */
    double scale_search_min_group_share = 0.5;

    void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
    void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
    /** \throws InputError naming the section, field and value, e.g.
     * "[GraphMatcher] max_groups = 0 violates max_groups >= 1". */
    void validate() const;
};

/** Matches a ground-truth graph and a map's graph. method = consistent (default): groups of
 * candidate pairs whose mutual distances agree in both maps (maximum cliques of the pairwise
 * consistency graph, one group per rigid part), grown by local rigid fits; in the result a
 * group is an "isomorphism" and grown pairs are "neighbour growing". method = paper (III-B):
 * subgraph isomorphisms by wavefront propagation from every unassigned vertex (Algorithm 1),
 * biggest first, then neighbour growing from the match's border. Spurious vertices are skipped.
 * `similarity` has a row per ground-truth vertex and a column per map vertex (attributeSimilarity()
 * or icpSimilarity()). Never throws on small or empty graphs: the match is then empty or partial,
 * with a message. Deterministic. \throws InputError on parameters or a matrix of wrong size. */
GraphMatch matchGraphs(const TopologyGraph& ground_truth, const TopologyGraph& map,
                       const SimilarityMatrix& similarity,
                       const GraphMatcherParameters& params = {});

}  // namespace mrpt_topoeval
