/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "buildings.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <queue>
#include <random>
#include <stdexcept>
#include <utility>

// How a building is made: a plan of convex free spaces (corridors, rooms, halls) laid out with a
// wall gap between neighbours, doors (rectangles through that gap) and openings (overlaps of
// corridor pieces) joining them, and columns inside halls. The plan is rasterised by sampling
// cell centres; walls are the free region dilated by the wall thickness, so every free cell is
// enclosed and everything beyond the outer wall stays unknown. The tour is a depth-first walk of
// the space graph through every door; moves inside a convex space are straight, moves around
// columns follow a clearance-aware grid search. Every layout is checked (size, connectivity,
// tour clearance) and redrawn from the same random stream if it fails, so results stay
// deterministic.

namespace mrpt_topoeval::validation
{
namespace
{
using Vec = Eigen::Vector2d;
using Poly = std::vector<Vec>;

constexpr double kTourClearance = 0.30;  //!< Required clearance of the tour [m].
constexpr double kPlanClearance = 0.33;  //!< Clearance the planner asks for (margin) [m].
constexpr double kApproach = 0.55;       //!< Tour points before/after a door, from its wall [m].

enum class Kind
{
    Corridor,
    Room,
    Hall
};

struct Space
{
    Poly poly;  // convex, counter-clockwise
    Kind kind = Kind::Room;
    Vec axis{1.0, 0.0};       // long axis (corridors: direction of travel)
    std::vector<Vec> visits;  // points the tour must reach (corridor ends, hall points)
};

/** A door (a rectangle through the wall gap) or an opening (overlap of two spaces). */
struct Portal
{
    int a = -1, b = -1;
    Vec c{0.0, 0.0};  // door middle (mid-wall) or a point in the overlap
    Vec n{1.0, 0.0};  // unit normal from a to b (doors)
    double width_m = 0.0;
    bool door = true;
};

struct Column
{
    Vec c{0.0, 0.0};
    double size_m = 0.5;
    bool round = true;
    Vec axis{1.0, 0.0};
    double length_m = 0.0;  //!< Along `axis` (square ones); 0: `size_m` (a rack: longer).
};

Vec perp(const Vec& v) { return {-v.y(), v.x()}; }
Vec rot(const Vec& v, double a)
{
    const double c = std::cos(a), s = std::sin(a);
    return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}
double cross(const Vec& a, const Vec& b) { return a.x() * b.y() - a.y() * b.x(); }

double signedArea(const Poly& p)
{
    double a = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) a += cross(p[i], p[(i + 1) % p.size()]);
    return 0.5 * a;
}

Poly ccw(Poly p)
{
    if (signedArea(p) < 0.0) std::reverse(p.begin(), p.end());
    return p;
}

bool isConvex(const Poly& p)
{
    if (p.size() < 3 || signedArea(p) <= 1e-9) return false;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const Vec& a = p[i];
        const Vec& b = p[(i + 1) % p.size()];
        const Vec& c = p[(i + 2) % p.size()];
        if (cross(b - a, c - b) < -1e-9) return false;
    }
    return true;
}

Vec centroid(const Poly& p)
{
    double a = 0.0;
    Vec c(0.0, 0.0);
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const Vec& u = p[i];
        const Vec& v = p[(i + 1) % p.size()];
        const double w = cross(u, v);
        a += w;
        c += (u + v) * w;
    }
    return c / (3.0 * a);
}

/** Rectangle origin + s u + d n, s in [s0, s1], d in [d0, d1]. */
Poly rect(const Vec& o, const Vec& u, const Vec& n, double s0, double s1, double d0, double d1)
{
    return ccw(
        {o + s0 * u + d0 * n, o + s1 * u + d0 * n, o + s1 * u + d1 * n, o + s0 * u + d1 * n});
}

/** Lower bound of the distance between two convex polygons (separating axes); negative when
 * they overlap. */
double gapBetween(const Poly& a, const Poly& b)
{
    double best = -1e9;
    auto axes = [&](const Poly& p, const Poly& q)
    {
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            const Vec e = p[(i + 1) % p.size()] - p[i];
            const Vec m = Vec(e.y(), -e.x()).normalized();  // outward for ccw
            double pmax = -1e18, qmin = 1e18;
            for (const Vec& v : p) pmax = std::max(pmax, m.dot(v));
            for (const Vec& v : q) qmin = std::min(qmin, m.dot(v));
            best = std::max(best, qmin - pmax);
        }
    };
    axes(a, b);
    axes(b, a);
    return best;
}

/** Convex hull (monotone chain), counter-clockwise. */
Poly convexHull(Poly pts)
{
    std::sort(pts.begin(), pts.end(),
              [](const Vec& a, const Vec& b)
              { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
    Poly h(2 * pts.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < pts.size(); ++i)
    {
        while (k >= 2 && cross(h[k - 1] - h[k - 2], pts[i] - h[k - 2]) <= 0) --k;
        h[k++] = pts[i];
    }
    for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;)
    {
        while (k >= t && cross(h[k - 1] - h[k - 2], pts[i] - h[k - 2]) <= 0) --k;
        h[k++] = pts[i];
    }
    h.resize(k - 1);
    return h;
}

/** The layout of one building, before rasterisation. */
struct Plan
{
    std::mt19937* rng = nullptr;
    double res = 0.05;
    double wall_m = 0.2;
    /** The building's extent [m]: its longer side in [min_extent_m, max_extent_m], its shorter
     * side at least min_width_m (a layout of another size is drawn again). */
    double min_extent_m = 25.0, max_extent_m = 59.0, min_width_m = 18.0;
    std::vector<Space> spaces;
    std::vector<Portal> portals;
    std::vector<Column> columns;

    double uni(double a, double b) { return std::uniform_real_distribution<double>(a, b)(*rng); }
    int pick(int a, int b) { return std::uniform_int_distribution<int>(a, b)(*rng); }
    bool chance(double p) { return uni(0.0, 1.0) < p; }
    /** Wall thickness drawn in [a, b], at least 2.5 cells so walls stay solid. */
    void drawWall(double a, double b) { wall_m = std::max(uni(a, b), 2.5 * res); }

    int add(Poly poly, Kind kind, const Vec& axis, std::vector<Vec> visits = {})
    {
        Space s;
        s.poly = ccw(std::move(poly));
        s.kind = kind;
        s.axis = axis.normalized();
        s.visits = std::move(visits);
        spaces.push_back(std::move(s));
        return static_cast<int>(spaces.size()) - 1;
    }
    /** True when `p` keeps at least the wall thickness from every space. */
    bool fits(const Poly& p) const
    {
        for (const Space& s : spaces)
            if (gapBetween(p, s.poly) < wall_m - 1e-6) return false;
        return true;
    }
    void door(int a, int b, const Vec& c, const Vec& n, double w)
    {
        portals.push_back({a, b, c, n.normalized(), w, true});
    }
    void opening(int a, int b, const Vec& c)
    {
        portals.push_back({a, b, c, Vec(1, 0), 0.0, false});
    }

    /** A corridor from p0 to p1, extended by ext0 / ext1 beyond its ends; visits its ends. */
    int corridor(const Vec& p0, const Vec& p1, double w, double ext0, double ext1)
    {
        const Vec u = (p1 - p0).normalized();
        const double len = (p1 - p0).norm();
        const double in = std::max(0.6, 0.5 * w);
        std::vector<Vec> visits;
        if (ext0 <= 0.0) visits.push_back(p0 + in * u);
        if (ext1 <= 0.0) visits.push_back(p1 - in * u);
        return add(rect(p0, u, perp(u), -ext0, len + ext1, -0.5 * w, 0.5 * w), Kind::Corridor, u,
                   visits);
    }
};

/** A row of rooms along a space's straight edge: the front line (rooms start there) is
 * origin + s u, rooms extend along n (away from the parent). */
struct RowSpec
{
    int parent = 0;
    Vec origin{0, 0}, u{1, 0}, n{0, 1};
    double s0 = 0.0, s1 = 10.0;
    double w_min = 2.5, w_max = 7.0;  // room width along the row [m]
    double d_min = 3.0, d_max = 8.0;  // room depth [m]
    double slant = 0.0;               // max |ds/dd| of the dividers between rooms
    double back_skew_m = 0.0;         // max difference of the depths at both sides [m]
    double door_min = 0.8, door_max = 1.6;
    double inner_door_p = 0.3;    // chance of a door between neighbouring rooms
    double min_room_depth = 2.5;  // rooms shrunk below this (collisions) are dropped
};

/** Lays out rooms along a row; rooms that collide are shrunk in depth or moved on. Returns the
 * number of rooms placed. */
int addRow(Plan& plan, const RowSpec& r)
{
    const double t = plan.wall_m;
    auto world = [&](double s, double d) { return Vec(r.origin + s * r.u + d * r.n); };
    int placed = 0;
    double a_l = r.s0, k_l = 0.0;  // left divider of the next room: s = a_l + k_l d
    int prev_room = -1;            // room just left of a_l (shares the divider), or -1
    double prev_k = 0.0, prev_a = 0.0, prev_depth = 0.0;
    bool prev_front = true;
    while (r.s1 - a_l >= r.w_min)
    {
        double w = plan.uni(r.w_min, r.w_max);
        double a_r = a_l + w;
        if (r.s1 - a_r < r.w_min + t) a_r = r.s1;
        if (a_r - a_l > r.w_max * 1.35) a_r = a_l + w;  // too wide to absorb: leave the end
        double k_r = (r.slant > 0.0 && a_r < r.s1 - 1e-9) ? plan.uni(-r.slant, r.slant) : 0.0;
        if (a_r >= r.s1 - 1e-9 && r.slant > 0.0) k_r = plan.uni(-r.slant, r.slant) * 0.5;
        const double d0 = plan.uni(r.d_min, r.d_max);
        double d_l = d0,
               d_r = std::clamp(d0 + plan.uni(-r.back_skew_m, r.back_skew_m), r.d_min, r.d_max);
        // Keep the room at least 2 m wide at its back.
        auto width_at = [&](double d) { return (a_r + k_r * d) - (a_l + k_l * d); };
        if (width_at(std::max(d_l, d_r)) < 2.0) k_r = k_l;
        auto make = [&](double scale)
        {
            const double dl = d_l * scale, dr = d_r * scale;
            return ccw({world(a_l, 0.0), world(a_r, 0.0), world(a_r + k_r * dr, dr),
                        world(a_l + k_l * dl, dl)});
        };
        // Largest depth scale that fits (bisection; smaller rooms never collide more).
        double scale = 1.0;
        bool ok = plan.fits(make(1.0));
        if (!ok)
        {
            const double lo_scale = r.min_room_depth / std::min(d_l, d_r);
            if (lo_scale < 1.0 && plan.fits(make(lo_scale)))
            {
                double lo = lo_scale, hi = 1.0;
                for (int i = 0; i < 24; ++i)
                {
                    const double mid = 0.5 * (lo + hi);
                    (plan.fits(make(mid)) ? lo = mid : hi = mid);
                }
                scale = lo;
                ok = true;
            }
        }
        Poly poly = make(scale);
        if (!ok || !isConvex(poly))
        {
            // Move on: the next room starts a little further, with a straight divider.
            a_l += 0.5;
            k_l = 0.0;
            prev_room = -1;
            continue;
        }
        d_l *= scale;
        d_r *= scale;
        const int id = plan.add(poly, Kind::Room, r.n);
        ++placed;
        // Inner door to the left neighbour along the shared divider.
        bool has_inner = false;
        const double shared = std::min(prev_depth, d_l);
        if (prev_room >= 0 && shared > 2.4 && plan.chance(r.inner_door_p))
        {
            const double dw = plan.uni(0.8, std::min(1.3, shared - 1.4));
            const double dc = plan.uni(0.7 + 0.5 * dw, shared - 0.7 - 0.5 * dw);
            const double q = std::sqrt(1.0 + prev_k * prev_k);
            const Vec dir_sd = Vec(1.0, -prev_k) / q;  // divider normal in (s, d), towards +s
            const Vec on_div(prev_a + prev_k * dc, dc);
            const Vec c_sd = on_div + 0.5 * t * dir_sd;
            const Vec nrm = dir_sd.x() * r.u + dir_sd.y() * r.n;
            plan.door(prev_room, id, world(c_sd.x(), c_sd.y()), nrm, dw);
            has_inner = true;
        }
        // Front door onto the parent (dropped now and then when an inner door reaches it).
        const bool front = !(has_inner && prev_front && plan.chance(0.3));
        if (front)
        {
            const double lo = std::max(a_l, a_l + k_l * 1.0), hi = std::min(a_r, a_r + k_r * 1.0);
            double dw = plan.uni(r.door_min, r.door_max);
            dw = std::min(dw, hi - lo - 0.7);
            if (dw < r.door_min) dw = r.door_min;
            const double c_lo = lo + 0.5 * dw + 0.32, c_hi = hi - 0.5 * dw - 0.32;
            const double sc = c_hi > c_lo ? plan.uni(c_lo, c_hi) : 0.5 * (lo + hi);
            plan.door(r.parent, id, world(sc, -0.5 * t), r.n, dw);
        }
        prev_room = id;
        prev_front = front;
        prev_k = k_r;
        prev_a = a_r;
        prev_depth = d_r;
        k_l = k_r;
        a_l = a_r + t * std::sqrt(1.0 + k_r * k_r);
    }
    return placed;
}

/** The two rows of rooms along a corridor `width_m` wide that starts at `a` and runs `length_m`
 * along the unit vector `u`: `row` on its left side, then on its right, each front line a wall
 * `wall_m` off the corridor's side, from a to its end. */
std::array<RowSpec, 2> rowsOnBothSides(const RowSpec& row, int parent, const Vec& a, const Vec& u,
                                       double length_m, double width_m, double wall_m)
{
    std::array<RowSpec, 2> rows{row, row};
    for (std::size_t k = 0; k < rows.size(); ++k)
    {
        RowSpec& r = rows[k];
        r.parent = parent;
        r.u = u;
        r.n = (k == 0 ? 1.0 : -1.0) * perp(u);
        r.origin = a + (0.5 * width_m + wall_m) * r.n;
        r.s0 = 0.0;
        r.s1 = length_m;
    }
    return rows;
}

/** Columns in rows at irregular spacing inside the axis-aligned box [x0,x1] x [y0,y1]. */
void addColumns(Plan& plan, double x0, double y0, double x1, double y1)
{
    const bool round = plan.chance(0.5);
    const double size = plan.uni(0.3, 0.8);
    const double margin = 2.6;
    auto positions = [&](double a, double b)
    {
        std::vector<double> v;
        for (double p = a + plan.uni(margin, margin + 1.5); p < b - margin; p += plan.uni(3.0, 6.5))
            v.push_back(p);
        return v;
    };
    std::vector<double> xs = positions(x0, x1), ys = positions(y0, y1);
    if (plan.chance(0.3) && ys.size() > 2)  // only a row or two along the hall
    {
        const std::size_t keep = plan.chance(0.5) ? 1 : 2;
        std::vector<double> sel;
        for (std::size_t i = 0; i < keep; ++i) sel.push_back(ys[(i + 1) * ys.size() / (keep + 1)]);
        ys = sel;
    }
    for (double y : ys)
        for (double x : xs)
            if (!plan.chance(0.1)) plan.columns.push_back({Vec(x, y), size, round, Vec(1, 0)});
}

/** Picks `count` positions in [lo, hi] for doors of the given widths, apart by `gap`. */
std::vector<double> spreadPositions(Plan& plan, double lo, double hi,
                                    const std::vector<double>& widths, double gap)
{
    std::vector<double> pos;
    for (double w : widths)
        for (int attempt = 0; attempt < 40; ++attempt)
        {
            if (hi - lo < w) break;
            const double c = plan.uni(lo + 0.5 * w, hi - 0.5 * w);
            bool clash = false;
            for (std::size_t i = 0; i < pos.size(); ++i)
                if (std::abs(pos[i] - c) < 0.5 * (w + widths[i]) + gap) clash = true;
            if (!clash)
            {
                pos.push_back(c);
                break;
            }
        }
    return pos;
}

// ---------------------------------------------------------------------------------------------
// Styles
// ---------------------------------------------------------------------------------------------

/** One or two long corridors lined with rooms of varied sizes, a branch or a twin corridor. */
void layoutCorridorOffice(Plan& p)
{
    p.drawWall(0.15, 0.3);
    const double t = p.wall_m;
    const double cw = p.uni(1.2, 3.0);
    const bool twin = p.chance(0.45);
    const double len = twin ? p.uni(30.0, 46.0) : p.uni(32.0, 54.0);
    const int main = p.corridor(Vec(0, 0), Vec(len, 0), cw, 0.0, 0.0);
    const double e0 = p.chance(0.5) ? p.uni(2.0, 5.0) : 0.0;  // dead-end stubs without rooms
    const double e1 = p.chance(0.6) ? p.uni(2.0, 6.0) : 0.0;
    RowSpec row;
    row.w_min = 2.5;
    row.w_max = 8.0;
    row.d_min = 3.0;
    row.d_max = 10.0;
    row.door_min = 0.7;
    row.door_max = 2.0;
    row.inner_door_p = 0.35;
    std::vector<RowSpec> rows;
    if (!twin)
    {
        // A branch corridor (T, or L at the end) going north, rooms on both of its sides.
        const double cw2 = p.uni(1.2, 3.0);
        const bool at_end = p.chance(0.3);
        const double xb = at_end ? len - cw2 : p.uni(0.3, 0.7) * len;
        const double lb = p.uni(14.0, 26.0);
        const int br =
            p.corridor(Vec(xb + 0.5 * cw2, 0.0), Vec(xb + 0.5 * cw2, 0.5 * cw + lb), cw2, 0.0, 0.0);
        p.spaces[br].visits.erase(p.spaces[br].visits.begin());
        p.opening(main, br, Vec(xb + 0.5 * cw2, 0.0));
        // A short dead-end stub southwards.
        if (p.chance(0.6))
        {
            const double sw = p.uni(1.2, 1.8), xs = p.uni(0.15, 0.85) * len;
            if (std::abs(xs - xb) > 6.0)
            {
                const int st =
                    p.corridor(Vec(xs, 0.0), Vec(xs, -0.5 * cw - p.uni(3.0, 7.0)), sw, 0.0, 0.0);
                p.spaces[st].visits.erase(p.spaces[st].visits.begin());
                p.opening(main, st, Vec(xs, 0.0));
            }
        }
        RowSpec r = row;
        r.parent = br;
        r.u = Vec(0, 1);
        r.s0 = 0.5 * cw + t;
        r.s1 = 0.5 * cw + lb;
        r.origin = Vec(xb - t, 0.0);
        r.n = Vec(-1, 0);
        rows.push_back(r);
        r.origin = Vec(xb + cw2 + t, 0.0);
        r.n = Vec(1, 0);
        rows.push_back(r);
    }
    else
    {
        // A second corridor north of a band of rooms, joined by one or two cross corridors.
        const double cw2 = p.uni(1.2, 3.0);
        const double band = p.uni(7.0, 14.0);
        const double y2 = 0.5 * cw + t + band + t + 0.5 * cw2;
        const double x2a = p.uni(0.0, 0.3) * len, x2b = len - p.uni(0.0, 0.3) * len;
        const int c2 = p.corridor(Vec(x2a, y2), Vec(x2b, y2), cw2, 0.0, 0.0);
        const int ncross = p.chance(0.5) ? 2 : 1;
        std::vector<double> widths;
        for (int i = 0; i < ncross; ++i) widths.push_back(p.uni(1.2, 2.5));
        const std::vector<double> xc = spreadPositions(p, x2a + 1.0, x2b - 1.0, widths, 6.0);
        for (std::size_t i = 0; i < xc.size(); ++i)
        {
            const int cc = p.corridor(Vec(xc[i], 0.0), Vec(xc[i], y2), widths[i], 0.0, 0.0);
            p.spaces[cc].visits.clear();
            p.opening(main, cc, Vec(xc[i], 0.0));
            p.opening(c2, cc, Vec(xc[i], y2));
        }
        RowSpec r = row;
        r.parent = c2;
        r.origin = Vec(0, y2 - 0.5 * cw2 - t);
        r.n = Vec(0, -1);
        r.s0 = x2a;
        r.s1 = x2b;
        r.d_max = band;
        rows.push_back(r);
        r.origin = Vec(0, y2 + 0.5 * cw2 + t);
        r.n = Vec(0, 1);
        r.d_max = 9.0;
        rows.push_back(r);
    }
    RowSpec r = row;
    r.parent = main;
    r.s0 = e0;
    r.s1 = len - e1;
    r.origin = Vec(0, 0.5 * cw + t);
    r.n = Vec(0, 1);
    rows.insert(rows.begin(), r);
    r.origin = Vec(0, -0.5 * cw - t);
    r.n = Vec(0, -1);
    rows.insert(rows.begin() + 1, r);
    for (const RowSpec& rs : rows) addRow(p, rs);
}

/** One or two column halls side by side, a corridor along them with rooms, rooms on the
 * halls' other sides. */
void layoutColumnHall(Plan& p)
{
    p.drawWall(0.15, 0.3);
    const double t = p.wall_m;
    const int nh = p.chance(0.55) ? 2 : 1;
    std::vector<double> hw, hh;
    for (int i = 0; i < nh; ++i)
    {
        hw.push_back(p.uni(15.0, nh == 2 ? 24.0 : 30.0));
        hh.push_back(p.uni(15.0, 28.0));
    }
    std::vector<int> halls;
    std::vector<double> hx0;
    double x = 0.0;
    for (int i = 0; i < nh; ++i)
    {
        const Vec c(x + 0.5 * hw[i], 0.5 * hh[i]);
        std::vector<Vec> visits = {c};
        for (double fx : {-0.27, 0.27})
            for (double fy : {-0.27, 0.27}) visits.push_back(c + Vec(fx * hw[i], fy * hh[i]));
        halls.push_back(p.add(rect(Vec(x, 0), Vec(1, 0), Vec(0, 1), 0, hw[i], 0, hh[i]), Kind::Hall,
                              Vec(1, 0), visits));
        addColumns(p, x, 0.0, x + hw[i], hh[i]);
        hx0.push_back(x);
        x += hw[i] + t;
    }
    const double total = x - t;
    // Corridor along the south, a dead end beyond the halls on one side.
    const double cw = p.uni(1.5, 3.0);
    const double ext_w = p.chance(0.5) ? p.uni(3.0, 8.0) : 0.0;
    const double ext_e = p.chance(0.5) ? p.uni(3.0, 8.0) : 0.0;
    const double yc = -t - 0.5 * cw;
    const int cor = p.corridor(Vec(-ext_w, yc), Vec(total + ext_e, yc), cw, 0.0, 0.0);
    for (int i = 0; i < nh; ++i)
    {
        std::vector<double> widths;
        const int nwide = p.pick(1, 2);
        for (int k = 0; k < nwide; ++k) widths.push_back(p.uni(2.5, 4.0));
        if (p.chance(0.6)) widths.push_back(0.8);
        const std::vector<double> pos =
            spreadPositions(p, hx0[i] + 0.4, hx0[i] + hw[i] - 0.4, widths, 2.0);
        for (std::size_t k = 0; k < pos.size(); ++k)
            p.door(cor, halls[i], Vec(pos[k], -0.5 * t), Vec(0, 1), widths[k]);
    }
    if (nh == 2)
    {
        std::vector<double> widths = {p.uni(2.5, 4.0)};
        if (p.chance(0.6)) widths.push_back(0.8);
        const double top = std::min(hh[0], hh[1]);
        const std::vector<double> pos = spreadPositions(p, 0.4, top - 0.4, widths, 2.0);
        for (std::size_t k = 0; k < pos.size(); ++k)
            p.door(halls[0], halls[1], Vec(hw[0] + 0.5 * t, pos[k]), Vec(1, 0), widths[k]);
    }
    RowSpec row;
    row.w_min = 2.5;
    row.w_max = 7.0;
    row.door_min = 0.8;
    row.door_max = 1.4;
    // Rooms south of the corridor.
    RowSpec r = row;
    r.parent = cor;
    r.origin = Vec(0, yc - 0.5 * cw - t);
    r.n = Vec(0, -1);
    r.s0 = -ext_w + (ext_w > 0 ? p.uni(0.0, 3.0) : 0.0);
    r.s1 = total + ext_e;
    r.d_min = 3.0;
    r.d_max = 8.0;
    addRow(p, r);
    // Rooms on the halls' north sides, and at the west and east ends.
    for (int i = 0; i < nh; ++i)
        if (p.chance(0.75))
        {
            RowSpec q = row;
            q.parent = halls[i];
            q.origin = Vec(0, hh[i] + t);
            q.n = Vec(0, 1);
            q.s0 = hx0[i] + (p.chance(0.5) ? p.uni(0.0, 4.0) : 0.0);
            q.s1 = hx0[i] + hw[i];
            q.d_min = 3.0;
            q.d_max = 6.0;
            addRow(p, q);
        }
    if (p.chance(0.5))
    {
        RowSpec q = row;
        q.parent = halls[0];
        q.origin = Vec(-t, 0);
        q.u = Vec(0, 1);
        q.n = Vec(-1, 0);
        q.s0 = 0.0;
        q.s1 = hh[0];
        q.d_min = 3.0;
        q.d_max = 5.5;
        addRow(p, q);
    }
    if (p.chance(0.5))
    {
        RowSpec q = row;
        q.parent = halls.back();
        q.origin = Vec(total + t, 0);
        q.u = Vec(0, 1);
        q.n = Vec(1, 0);
        q.s0 = 0.0;
        q.s1 = hh.back();
        q.d_min = 3.0;
        q.d_max = 5.5;
        addRow(p, q);
    }
}

/** An irregular convex room at the far end of a corridor end (p_end, direction u, width cw). */
void addEndRoom(Plan& p, int cor, const Vec& p_end, const Vec& u, double cw)
{
    const double t = p.wall_m;
    const Vec n = perp(u);
    const Vec o = p_end + t * u;
    const double a = p.uni(std::max(1.5, 0.5 * cw + 0.3), 3.5);
    const double b = p.uni(std::max(1.5, 0.5 * cw + 0.3), 3.5);
    Poly pts = {o - a * n, o + b * n};
    const int extra = p.pick(3, 5);
    for (int i = 0; i < extra; ++i) pts.push_back(o + p.uni(2.0, 7.0) * u + p.uni(-4.0, 4.0) * n);
    Poly hull = convexHull(pts);
    for (int shrink = 0; shrink < 6 && !p.fits(hull); ++shrink)
        for (Vec& v : hull) v = o + 0.8 * (v - o);  // pull towards the door
    if (!p.fits(hull) || std::abs(signedArea(hull)) < 8.0) return;
    const int id = p.add(hull, Kind::Room, u);
    const double dw = std::min(p.uni(0.8, 2.0), cw - 0.15);
    p.door(cor, id, p_end + 0.5 * t * u, u, dw);
}

/** A corridor with bends of 20-70 degrees, a wing at a random angle, trapezoid rooms. */
void layoutAngled(Plan& p)
{
    p.drawWall(0.15, 0.25);
    const double t = p.wall_m;
    const double cw = p.uni(1.4, 2.6);
    const int nseg = p.pick(3, 4);
    double heading = p.uni(0.0, M_PI);
    double sign = p.chance(0.5) ? 1.0 : -1.0;
    std::vector<Vec> pts = {Vec(0, 0)};
    std::vector<double> lens;
    for (int i = 0; i < nseg; ++i)
    {
        if (i > 0)
        {
            heading += sign * p.uni(20.0, 70.0) * M_PI / 180.0;
            sign = p.chance(0.75) ? -sign : sign;
        }
        lens.push_back(p.uni(9.0, 16.0));
        pts.push_back(pts.back() + lens.back() * Vec(std::cos(heading), std::sin(heading)));
    }
    std::vector<int> segs;
    for (int i = 0; i < nseg; ++i)
    {
        const int id = p.corridor(pts[i], pts[i + 1], cw, i > 0 ? 0.5 * cw : 0.0,
                                  i + 1 < nseg ? 0.5 * cw : 0.0);
        if (i > 0) p.opening(segs.back(), id, pts[i]);
        segs.push_back(id);
    }
    // The wing: a straight corridor leaving a middle segment at a random angle.
    const int ws = p.pick(0, nseg - 1);
    const Vec su = (pts[ws + 1] - pts[ws]).normalized();
    const Vec q = pts[ws] + p.uni(0.35, 0.65) * lens[ws] * su;
    const double phi = (p.chance(0.5) ? 1.0 : -1.0) * p.uni(40.0, 80.0) * M_PI / 180.0;
    const Vec wu = rot(su, phi);
    const double wcw = p.uni(1.3, 2.4);
    const double wlen = p.uni(8.0, 15.0);
    const Vec wend = q + wlen * wu;
    const int wing = p.corridor(q, wend, wcw, 0.0, 0.0);
    p.spaces[wing].visits.erase(p.spaces[wing].visits.begin());
    p.opening(segs[ws], wing, q);
    // Irregular rooms at the ends.
    if (p.chance(0.6)) addEndRoom(p, wing, wend, wu, wcw);
    if (p.chance(0.6))
        addEndRoom(p, segs.back(), pts.back(), (pts[nseg] - pts[nseg - 1]).normalized(), cw);
    RowSpec row;
    row.w_min = 2.8;
    row.w_max = 6.5;
    row.d_min = 3.0;
    row.d_max = 7.0;
    row.slant = 0.55;
    row.back_skew_m = 2.0;
    row.door_min = 0.8;
    row.door_max = 2.0;
    row.inner_door_p = 0.3;
    row.min_room_depth = 2.6;
    auto rowsAlong = [&](int parent, const Vec& a, const Vec& b, double w)
    {
        for (const RowSpec& r :
             rowsOnBothSides(row, parent, a, (b - a).normalized(), (b - a).norm(), w, t))
            addRow(p, r);
    };
    rowsAlong(wing, q, wend, wcw);
    for (int i = 0; i < nseg; ++i) rowsAlong(segs[i], pts[i], pts[i + 1], cw);
}

/** Two parallel wings joined by two connectors (a loop), plus a perpendicular wing and a hall
 * wing; all rotated by a multiple of 90 degrees. */
void layoutMultiWing(Plan& p)
{
    p.drawWall(0.15, 0.25);
    const double t = p.wall_m;
    const int nw = p.pick(2, 4);
    RowSpec row;
    row.w_min = 2.5;
    row.w_max = 6.5;
    row.d_min = 3.0;
    row.d_max = 7.0;
    row.door_min = 0.8;
    row.door_max = 1.8;
    row.inner_door_p = 0.25;
    std::vector<RowSpec> rows;
    auto wingRows = [&](int parent, const Vec& a, const Vec& b, double w, double d_max)
    {
        for (RowSpec r :
             rowsOnBothSides(row, parent, a, (b - a).normalized(), (b - a).norm(), w, t))
        {
            r.d_max = d_max;
            rows.push_back(r);
        }
    };
    // Wing A along y = 0, wing B along y = sep.
    const double la = p.uni(18.0, 30.0), cwa = p.uni(1.4, 3.0);
    const double lb = p.uni(15.0, 27.0), cwb = p.uni(1.4, 3.0);
    const double da = p.uni(4.0, 7.0), db = p.uni(4.0, 7.0);
    const double sep = 0.5 * cwa + 0.5 * cwb + da + db + 4.0 * t + p.uni(3.0, 9.0);
    const double xb0 = p.uni(-0.25, 0.35) * la;
    const int wa = p.corridor(Vec(0, 0), Vec(la, 0), cwa, 0.0, 0.0);
    const int wb = p.corridor(Vec(xb0, sep), Vec(xb0 + lb, sep), cwb, 0.0, 0.0);
    const double ov0 = std::max(0.0, xb0) + 1.5, ov1 = std::min(la, xb0 + lb) - 1.5;
    std::vector<double> widths = {p.uni(1.2, 3.2), p.uni(1.2, 3.2)};
    const std::vector<double> xc = spreadPositions(p, ov0, ov1, widths, 5.0);
    if (xc.size() < 2) return;  // no loop: rejected by the caller's checks
    for (std::size_t i = 0; i < xc.size(); ++i)
    {
        const int c = p.corridor(Vec(xc[i], 0), Vec(xc[i], sep), widths[i], 0.0, 0.0);
        p.spaces[c].visits.clear();
        p.opening(wa, c, Vec(xc[i], 0));
        p.opening(wb, c, Vec(xc[i], sep));
    }
    wingRows(wa, Vec(0, 0), Vec(la, 0), cwa, da);
    wingRows(wb, Vec(xb0, sep), Vec(xb0 + lb, sep), cwb, db);
    if (nw >= 3)
    {
        // Wing C: perpendicular, reached by a connector continuing A's or B's axis (L or T).
        const bool from_a = p.chance(0.5);
        const bool east = p.chance(0.5);
        const double y = from_a ? 0.0 : sep;
        const double xe = from_a ? (east ? la : 0.0) : (east ? xb0 + lb : xb0);
        const double dir = east ? 1.0 : -1.0;
        const double lc = p.uni(3.0, 8.0) + (from_a ? da : db), cwc = p.uni(1.2, 3.0);
        const double xw = xe + dir * lc;
        const int con = p.corridor(Vec(xe, y), Vec(xw, y), cwc, 0.0, 0.0);
        p.spaces[con].visits.clear();
        p.opening(from_a ? wa : wb, con, Vec(xe, y));
        const double lw = p.uni(12.0, 22.0), cww = p.uni(1.4, 3.0);
        const double yw0 = y - p.uni(0.1, 0.9) * lw;
        const int wc = p.corridor(Vec(xw, yw0), Vec(xw, yw0 + lw), cww, 0.0, 0.0);
        p.opening(con, wc, Vec(xw, y));
        wingRows(wc, Vec(xw, yw0), Vec(xw, yw0 + lw), cww, p.uni(4.0, 7.0));
    }
    if (nw >= 4)
    {
        // Wing D: a hall beyond B's outer rooms (or A's), reached by a straight connector.
        const bool above = p.chance(0.5);
        const double yb = above ? sep : 0.0, dd = above ? db : da;
        const double x0 = above ? xb0 : 0.0, x1 = above ? xb0 + lb : la;
        const double cwd = p.uni(1.2, 3.0);
        const double xd = p.uni(x0 + 2.0, x1 - 2.0);
        const double hw = p.uni(10.0, 18.0), hh = p.uni(8.0, 14.0);
        const double s = above ? 1.0 : -1.0;
        const double yh = yb + s * (0.5 * (above ? cwb : cwa) + dd + 2 * t + p.uni(2.0, 5.0));
        const double hx0 = xd - p.uni(0.2, 0.8) * hw;
        const Poly hall = rect(Vec(hx0, yh), Vec(1, 0), Vec(0, s), 0.0, hw, 0.0, hh);
        const Vec hc = centroid(ccw(hall));
        const int h = p.add(hall, Kind::Hall, Vec(1, 0), {hc});
        const int con = p.corridor(Vec(xd, yb), Vec(xd, yh + s * 0.5 * cwd), cwd, 0.0, 0.0);
        p.spaces[con].visits.clear();
        p.opening(above ? wb : wa, con, Vec(xd, yb));
        p.opening(con, h, Vec(xd, yh + s * 0.5 * cwd));
        RowSpec r = row;
        r.parent = h;
        r.origin = Vec(hx0, yh + s * (hh + t));
        r.n = Vec(0, s);
        r.s0 = 0.0;
        r.s1 = hw;
        r.d_max = 5.0;
        rows.push_back(r);
    }
    for (const RowSpec& r : rows) addRow(p, r);
    if (p.chance(0.5))  // turn the whole building by 90 degrees
    {
        auto turn = [](Vec& v) { v = Vec(-v.y(), v.x()); };
        for (Space& s : p.spaces)
        {
            for (Vec& v : s.poly) turn(v);
            for (Vec& v : s.visits) turn(v);
            turn(s.axis);
        }
        for (Portal& d : p.portals)
        {
            turn(d.c);
            turn(d.n);
        }
        for (Column& c : p.columns)
        {
            turn(c.c);
            turn(c.axis);
        }
    }
}

/** A rotunda (held out, session 36; never in the standard corpus the matcher was tuned on): a
 * ring corridor of 8-14 straight pieces round a courtyard or a central hall, rooms along its
 * outside and, on some pieces, its inside; spokes to the hall; a wing leaving the ring outwards.
 * Its walls turn by about 20-55 degrees at every piece and it is nearly symmetric under
 * rotation, which no standard style is. */
void layoutRing(Plan& p)
{
    p.drawWall(0.15, 0.3);
    const double t = p.wall_m;
    const double cw = p.uni(1.4, 2.8);
    const int n = p.pick(8, 14);
    const double radius = p.uni(10.0, 15.0);  // of the corridor's centre line [m]
    const double a0 = p.uni(0.0, 2.0 * M_PI);
    const double step = 2.0 * M_PI / n;
    std::vector<Vec> pts;
    for (int k = 0; k < n; ++k)
    {
        const double a = a0 + step * (k + p.uni(-0.2, 0.2));
        const double r = radius * p.uni(0.93, 1.07);
        pts.push_back(r * Vec(std::cos(a), std::sin(a)));
    }
    // Half the turn at each corner; pieces are extended to meet on the outside (a mitre).
    std::vector<double> half_turn(n);
    for (int k = 0; k < n; ++k)
    {
        const Vec u0 = (pts[k] - pts[(k + n - 1) % n]).normalized();
        const Vec u1 = (pts[(k + 1) % n] - pts[k]).normalized();
        half_turn[k] = 0.5 * std::acos(std::clamp(u0.dot(u1), -1.0, 1.0));
    }
    std::vector<int> ring;
    for (int k = 0; k < n; ++k)
    {
        const int k1 = (k + 1) % n;
        ring.push_back(p.corridor(pts[k], pts[k1], cw, 0.5 * cw * std::tan(half_turn[k]) + 0.05,
                                  0.5 * cw * std::tan(half_turn[k1]) + 0.05));
    }
    for (int k = 0; k < n; ++k) p.opening(ring[(k + n - 1) % n], ring[k], pts[k]);
    // The inside: a hall reached by one or two spokes (else a courtyard, left unknown).
    const bool hall = p.chance(0.55);
    std::vector<int> spoke_pieces;
    double hall_r = 0.0;
    if (hall)
    {
        hall_r = p.uni(3.0, std::min(6.0, radius - 0.5 * cw - 5.0));
        const int m = p.pick(6, 10);
        Poly poly;
        const double b0 = p.uni(0.0, 2.0 * M_PI);
        for (int i = 0; i < m; ++i)
        {
            const double b = b0 + 2.0 * M_PI * i / m;
            poly.push_back(hall_r * Vec(std::cos(b), std::sin(b)));
        }
        std::vector<Vec> visits = {Vec(0, 0)};
        const int h = p.add(poly, Kind::Hall, Vec(1, 0), visits);
        const int ns = p.chance(0.5) ? 2 : 1;
        const int k0 = p.pick(0, n - 1);
        for (int i = 0; i < ns; ++i)
        {
            const int k = (k0 + i * (n / 2 + p.pick(-1, 1))) % n;
            const Vec mid = 0.5 * (pts[k] + pts[(k + 1) % n]);
            const Vec u = mid.normalized();
            const double sw = p.uni(1.2, 2.2);
            const Vec a = (hall_r * std::cos(M_PI / m) - 0.3) * u;
            const int s = p.corridor(a, mid, sw, 0.0, 0.0);
            p.spaces[s].visits.clear();
            p.opening(h, s, a);
            p.opening(ring[k], s, mid);
            spoke_pieces.push_back(k);
        }
    }
    // A wing leaving the ring outwards: a corridor with rooms on both sides.
    RowSpec row;
    row.w_min = 2.6;
    row.w_max = 6.0;
    row.d_min = 3.0;
    row.d_max = 7.0;
    row.slant = 0.35;
    row.back_skew_m = 1.0;
    row.door_min = 0.8;
    row.door_max = 1.6;
    row.inner_door_p = 0.3;
    row.min_room_depth = 2.6;
    std::vector<RowSpec> rows;
    if (p.chance(0.6))
    {
        const int k = p.pick(0, n - 1);
        const Vec mid = 0.5 * (pts[k] + pts[(k + 1) % n]);
        const Vec u = mid.normalized();
        const double ww = p.uni(1.3, 2.4), wl = p.uni(8.0, 14.0);
        const Vec end = mid + wl * u;
        const int w = p.corridor(mid, end, ww, 0.0, 0.0);
        p.spaces[w].visits.erase(p.spaces[w].visits.begin());
        p.opening(ring[k], w, mid);
        for (RowSpec r : rowsOnBothSides(row, w, mid, u, wl, ww, t))
        {
            r.s0 = 0.5 * cw + t + 1.0;
            rows.push_back(r);
        }
    }
    for (int k = 0; k < n; ++k)
    {
        const int k1 = (k + 1) % n;
        const Vec a = pts[k], b = pts[k1];
        const Vec u = (b - a).normalized();
        const Vec out = perp(u).dot(0.5 * (a + b)) > 0.0 ? perp(u) : Vec(-perp(u));
        RowSpec r = row;
        r.parent = ring[k];
        r.u = u;
        r.n = out;
        r.origin = a + (0.5 * cw + t) * out;
        r.s0 = 0.1;
        r.s1 = (b - a).norm() - 0.1;
        rows.push_back(r);
        const bool spoke =
            std::find(spoke_pieces.begin(), spoke_pieces.end(), k) != spoke_pieces.end();
        if (!spoke && p.chance(hall ? 0.7 : 0.5))
        {
            // Inside, neighbouring rows converge: each keeps clear of the corners' bisectors.
            r.n = -out;
            r.origin = a + (0.5 * cw + t) * r.n;
            r.d_max = std::min(5.0, radius - 0.5 * cw - 2.0 * t - (hall ? hall_r + 0.5 : 2.0));
            r.d_min = std::min(r.d_min, r.d_max);
            r.slant = 0.0;
            const double reach = 0.5 * cw + t + r.d_max;
            r.s0 = reach * std::tan(half_turn[k]) + 0.6 * t;
            r.s1 = (b - a).norm() - reach * std::tan(half_turn[k1]) - 0.6 * t;
            rows.push_back(r);
        }
    }
    for (const RowSpec& r : rows) addRow(p, r);
}

/** A warehouse (held out, session 36): a hall of parallel racks (long thin obstacles, 0.8-1.4 m
 * deep) in rows split by one or two cross aisles, a dock area of pallets along the front, and
 * offices along a side. Its aisles repeat at one spacing, a lattice no standard style has but
 * the column hall's columns. */
void layoutWarehouse(Plan& p)
{
    p.drawWall(0.2, 0.35);
    const double t = p.wall_m;
    const double hw = p.uni(26.0, 44.0), hh = p.uni(20.0, 32.0);
    const double dock = p.uni(4.0, 7.0);  // open band along the front (y = 0) [m]
    const double depth = p.uni(0.8, 1.4), aisle = p.uni(2.2, 3.4);
    const double back = p.uni(1.8, 3.5);  // aisle along the back wall [m]
    const double west = p.uni(2.5, 4.5), east = p.uni(2.5, 4.5);
    // Cross aisles split every rack row into segments.
    const int ncross = p.pick(0, 2);
    std::vector<double> cuts = {west};
    for (int i = 1; i <= ncross; ++i)
    {
        const double c = west + (hw - west - east) * i / (ncross + 1) + p.uni(-2.0, 2.0);
        const double w = p.uni(2.5, 4.0);
        cuts.push_back(c - 0.5 * w);
        cuts.push_back(c + 0.5 * w);
    }
    cuts.push_back(hw - east);
    std::vector<Vec> visits = {Vec(0.5 * hw, 0.5 * dock)};
    const bool round = p.chance(0.4);
    for (double y = dock; y + depth <= hh - back; y += depth + aisle)
    {
        // Every row's segments; a segment now and then missing (an open floor area) or short.
        for (std::size_t k = 0; k + 1 < cuts.size(); k += 2)
        {
            const double x0 = cuts[k], x1 = cuts[k + 1];
            if (x1 - x0 < 4.0 || p.chance(0.08)) continue;
            const double a = x0 + (p.chance(0.2) ? p.uni(0.0, 0.3) * (x1 - x0) : 0.0);
            Column c;
            c.c = Vec(0.5 * (a + x1), y + 0.5 * depth);
            c.size_m = depth;
            c.length_m = x1 - a;
            c.round = false;
            p.columns.push_back(c);
        }
        // The aisle above the row: points along each of its segments, every 15 m at most, so
        // that the tour drives the aisles as a robot mapping a warehouse does (from their ends
        // a 10 m laser leaves their middles unknown).
        const double ya = y + depth + 0.5 * aisle;
        if (ya < hh - 0.5)
            for (std::size_t k = 0; k + 1 < cuts.size(); k += 2)
            {
                const double x0 = cuts[k], x1 = cuts[k + 1];
                const int m = std::max(1, static_cast<int>(std::ceil((x1 - x0) / 15.0)));
                for (int i = 0; i < m; ++i)
                    visits.push_back(Vec(x0 + (x1 - x0) * (i + 0.5) / m, ya));
            }
    }
    // Pallets in the dock area.
    for (double x = p.uni(2.0, 5.0); x < hw - 2.0; x += p.uni(3.0, 7.0))
        if (p.chance(0.35))
        {
            Column c;
            c.c = Vec(x, p.uni(1.2, std::max(1.3, dock - 1.4)));
            c.size_m = p.uni(0.8, 1.2);
            c.round = round && p.chance(0.3);
            p.columns.push_back(c);
        }
    const int h =
        p.add(rect(Vec(0, 0), Vec(1, 0), Vec(0, 1), 0, hw, 0, hh), Kind::Hall, Vec(1, 0), visits);
    // Offices: a row of rooms along the west or east wall, or along the front.
    RowSpec r;
    r.parent = h;
    r.w_min = 2.8;
    r.w_max = 6.0;
    r.d_min = 3.0;
    r.d_max = 6.0;
    r.door_min = 0.8;
    r.door_max = 1.4;
    r.inner_door_p = 0.35;
    const int side = p.pick(0, 2);
    if (side == 0)
    {
        r.origin = Vec(-t, 0);
        r.u = Vec(0, 1);
        r.n = Vec(-1, 0);
        r.s0 = p.uni(0.0, 0.4) * hh;
        r.s1 = hh;
    }
    else if (side == 1)
    {
        r.origin = Vec(hw + t, 0);
        r.u = Vec(0, 1);
        r.n = Vec(1, 0);
        r.s0 = 0.0;
        r.s1 = hh - p.uni(0.0, 0.4) * hh;
    }
    else
    {
        r.origin = Vec(0, -t);
        r.n = Vec(0, -1);
        r.s0 = p.uni(0.0, 0.3) * hw;
        r.s1 = r.s0 + p.uni(0.4, 0.7) * hw;
    }
    addRow(p, r);
    // Sometimes a second, smaller hall (a cold store) through a wide door in the back wall.
    if (p.chance(0.4))
    {
        const double sw = p.uni(8.0, 14.0), sh = p.uni(6.0, 10.0);
        const double sx = p.uni(0.0, hw - sw);
        const Poly poly = rect(Vec(sx, hh + t), Vec(1, 0), Vec(0, 1), 0, sw, 0, sh);
        if (p.fits(poly))
        {
            const Vec c = centroid(ccw(poly));
            const int s = p.add(poly, Kind::Hall, Vec(1, 0), {c});
            const double dw = p.uni(2.0, 3.5);
            const double dx = p.uni(sx + 0.5 * dw + 0.5, sx + sw - 0.5 * dw - 0.5);
            p.door(h, s, Vec(dx, hh + 0.5 * t), Vec(0, 1), dw);
        }
    }
}

/** A house (held out, session 36): a hallway 0.9-1.4 m wide, straight or with a bend, lined
 * with bedrooms, a bathroom and closets, a living room at one end through a wide opening, now
 * and then a kitchen beside it. 10-25 m across: the small graphs (10-30 vertices) of a home
 * robot's map, which the standard styles (25-59 m) never draw. */
void layoutHouse(Plan& p)
{
    p.drawWall(0.1, 0.2);
    const double t = p.wall_m;
    p.min_extent_m = 10.0;
    p.max_extent_m = 25.0;
    p.min_width_m = 7.0;
    const double hw = p.uni(0.9, 1.4);
    const double len = p.uni(6.0, 12.0);
    const int hall = p.corridor(Vec(0, 0), Vec(len, 0), hw, 0.0, 0.0);
    RowSpec row;
    row.w_min = 1.8;
    row.w_max = 4.5;
    row.d_min = 2.2;
    row.d_max = 4.5;
    row.door_min = 0.7;
    row.door_max = 0.9;
    row.inner_door_p = 0.15;
    row.min_room_depth = 2.0;
    std::vector<RowSpec> rows;
    for (RowSpec r : rowsOnBothSides(row, hall, Vec(0, 0), Vec(1, 0), len, hw, t))
    {
        r.s0 = p.chance(0.4) ? p.uni(0.5, 2.0) : 0.0;
        rows.push_back(r);
    }
    // A bend: a second hallway leaving the far end at a right angle, rooms on its outer side.
    if (p.chance(0.4))
    {
        const double side = p.chance(0.5) ? 1.0 : -1.0;
        const double len2 = p.uni(4.0, 7.0);
        const Vec a(len - 0.5 * hw, 0.0), b(len - 0.5 * hw, side * (0.5 * hw + len2));
        const int h2 = p.corridor(a, b, hw, 0.0, 0.0);
        p.spaces[h2].visits.erase(p.spaces[h2].visits.begin());
        p.opening(hall, h2, a);
        RowSpec r = row;
        r.parent = h2;
        r.u = Vec(0, side);
        r.n = Vec(1, 0);
        r.origin = Vec(len + t, 0.0);
        r.s0 = 0.5 * hw + t + 0.2;
        r.s1 = 0.5 * hw + len2;
        rows.push_back(r);
    }
    // The living room at the hallway's near end, through a wide opening; a kitchen beside it.
    const double lw = p.uni(4.0, 7.0), lh = p.uni(4.0, 7.5);
    const double y0 = -p.uni(0.3, 0.7) * lh;
    const Poly living = rect(Vec(-t - lw, y0), Vec(1, 0), Vec(0, 1), 0.0, lw, 0.0, lh);
    const Vec lc = centroid(ccw(living));
    const int lr = p.add(living, Kind::Hall, Vec(1, 0), {lc});
    const double ow = std::min(p.uni(1.2, 2.4), hw + 1.0);
    p.door(hall, lr, Vec(-0.5 * t, 0.0), Vec(-1, 0), std::min(ow, hw));
    if (p.chance(0.6))
    {
        const double kw = p.uni(2.5, 4.0);
        const double side = p.chance(0.5) ? 1.0 : -1.0;
        const double ky0 = side > 0 ? y0 + lh + t : y0 - t - kw;
        const Poly kitchen =
            rect(Vec(-t - lw, ky0), Vec(1, 0), Vec(0, 1), 0.0, p.uni(3.0, lw), 0.0, kw);
        if (p.fits(kitchen))
        {
            const int k = p.add(kitchen, Kind::Room, Vec(1, 0));
            const double dw = p.uni(0.8, 1.6);
            p.door(lr, k,
                   Vec(-t - lw + p.uni(0.5 + 0.5 * dw, 2.5),
                       side > 0 ? y0 + lh + 0.5 * t : y0 - 0.5 * t),
                   Vec(0, side), dw);
        }
    }
    for (const RowSpec& r : rows) addRow(p, r);
}

// ---------------------------------------------------------------------------------------------
// Rasterisation and checks
// ---------------------------------------------------------------------------------------------

enum : std::uint8_t
{
    kUnknown = 0,
    kWall = 1,
    kFree = 2
};

struct Raster
{
    int nx = 0, ny = 0;
    double x0 = 0.0, y0 = 0.0, res = 0.05;  // world of the lower-left corner of cell (0, 0)
    std::vector<std::uint8_t> lab;
    cv::Mat dt;  // distance of a free cell centre to the nearest non-free cell centre [cells]

    Vec centre(int cx, int cy) const { return {x0 + (cx + 0.5) * res, y0 + (cy + 0.5) * res}; }
    bool free(int cx, int cy) const
    {
        return cx >= 0 && cy >= 0 && cx < nx && cy < ny && lab[cy * nx + cx] == kFree;
    }
    void fillConvex(const Poly& poly, std::uint8_t v, std::vector<std::uint8_t>& img) const
    {
        double xmin = 1e18, xmax = -1e18, ymin = 1e18, ymax = -1e18;
        for (const Vec& p : poly)
        {
            xmin = std::min(xmin, p.x());
            xmax = std::max(xmax, p.x());
            ymin = std::min(ymin, p.y());
            ymax = std::max(ymax, p.y());
        }
        const int cx0 = std::max(0, static_cast<int>(std::floor((xmin - x0) / res)));
        const int cx1 = std::min(nx - 1, static_cast<int>(std::ceil((xmax - x0) / res)));
        const int cy0 = std::max(0, static_cast<int>(std::floor((ymin - y0) / res)));
        const int cy1 = std::min(ny - 1, static_cast<int>(std::ceil((ymax - y0) / res)));
        for (int cy = cy0; cy <= cy1; ++cy)
            for (int cx = cx0; cx <= cx1; ++cx)
            {
                const Vec c = centre(cx, cy);
                bool in = true;
                for (std::size_t i = 0; i < poly.size() && in; ++i)
                    in = cross(poly[(i + 1) % poly.size()] - poly[i], c - poly[i]) >= 0.0;
                if (in) img[cy * nx + cx] = v;
            }
    }
    /** Distance from p to the nearest non-free cell (its square), capped at `cap`. */
    double clearance(const Vec& p, double cap) const
    {
        const int cx = static_cast<int>(std::floor((p.x() - x0) / res));
        const int cy = static_cast<int>(std::floor((p.y() - y0) / res));
        if (!free(cx, cy)) return 0.0;
        const double lower = (dt.at<float>(cy, cx) - 1.5) * res;
        if (lower >= cap) return cap;
        const int r = static_cast<int>(std::ceil(cap / res)) + 1;
        double best = cap;
        for (int y = cy - r; y <= cy + r; ++y)
            for (int x = cx - r; x <= cx + r; ++x)
            {
                if (free(x, y)) continue;
                const Vec c = centre(x, y);
                const double dx = std::max(0.0, std::abs(p.x() - c.x()) - 0.5 * res);
                const double dy = std::max(0.0, std::abs(p.y() - c.y()) - 0.5 * res);
                best = std::min(best, std::hypot(dx, dy));
            }
        return best;
    }
    /** Smallest clearance along a segment sampled every 0.025 m. */
    double segmentClearance(const Vec& a, const Vec& b, double cap) const
    {
        const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / 0.025)));
        double best = cap;
        for (int i = 0; i <= n && best > 0.0; ++i)
            best = std::min(best, clearance(a + (b - a) * (double(i) / n), cap));
        return best;
    }
};

Raster rasterise(const Plan& plan, const mrpt::maps::COccupancyGridMap2D& grid)
{
    Raster r;
    r.nx = static_cast<int>(grid.getSizeX());
    r.ny = static_cast<int>(grid.getSizeY());
    r.res = grid.getResolution();
    r.x0 = grid.getXMin();
    r.y0 = grid.getYMin();
    std::vector<std::uint8_t> free_img(r.nx * r.ny, 0), col_img(r.nx * r.ny, 0);
    for (const Space& s : plan.spaces) r.fillConvex(s.poly, 255, free_img);
    const double half_depth = 0.5 * plan.wall_m + 1.5 * r.res;
    for (const Portal& d : plan.portals)
        if (d.door)
            r.fillConvex(rect(d.c, perp(d.n), d.n, -0.5 * d.width_m, 0.5 * d.width_m, -half_depth,
                              half_depth),
                         255, free_img);
    for (const Column& c : plan.columns)
    {
        if (c.round)
        {
            Poly circle;
            for (int i = 0; i < 32; ++i)
                circle.push_back(c.c + 0.5 * c.size_m *
                                           Vec(std::cos(i * M_PI / 16), std::sin(i * M_PI / 16)));
            r.fillConvex(circle, 255, col_img);
        }
        else
        {
            const double len = c.length_m > 0.0 ? c.length_m : c.size_m;
            r.fillConvex(rect(c.c, c.axis, perp(c.axis), -0.5 * len, 0.5 * len, -0.5 * c.size_m,
                              0.5 * c.size_m),
                         255, col_img);
        }
    }
    const int rad = std::max(2, static_cast<int>(std::lround(plan.wall_m / r.res)));
    cv::Mat free_m(r.ny, r.nx, CV_8U, free_img.data()), wall_m;
    cv::dilate(free_m, wall_m,
               cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * rad + 1, 2 * rad + 1)));
    r.lab.assign(r.nx * r.ny, kUnknown);
    for (int i = 0; i < r.nx * r.ny; ++i)
    {
        if (wall_m.data[i]) r.lab[i] = kWall;
        if (free_img[i]) r.lab[i] = kFree;
        if (col_img[i]) r.lab[i] = kWall;
    }
    cv::Mat mask(r.ny, r.nx, CV_8U);
    for (int i = 0; i < r.nx * r.ny; ++i) mask.data[i] = r.lab[i] == kFree ? 255 : 0;
    cv::distanceTransform(mask, r.dt, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    return r;
}

/** Free cells not reached from the largest free region: small slivers become wall, a larger
 * one fails the building. */
bool enforceConnected(Raster& r)
{
    std::vector<int> comp(r.lab.size(), -1), sizes;
    for (int start = 0; start < r.nx * r.ny; ++start)
    {
        if (r.lab[start] != kFree || comp[start] >= 0) continue;
        const int id = static_cast<int>(sizes.size());
        int count = 0;
        std::vector<int> stack = {start};
        comp[start] = id;
        while (!stack.empty())
        {
            const int i = stack.back();
            stack.pop_back();
            ++count;
            const int x = i % r.nx, y = i / r.nx;
            const int nb[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
            for (const auto& d : nb)
            {
                const int xx = x + d[0], yy = y + d[1];
                if (!r.free(xx, yy)) continue;
                const int j = yy * r.nx + xx;
                if (comp[j] < 0)
                {
                    comp[j] = id;
                    stack.push_back(j);
                }
            }
        }
        sizes.push_back(count);
    }
    if (sizes.empty()) return false;
    const int main = static_cast<int>(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
    const int sliver = static_cast<int>(0.5 / (r.res * r.res));
    for (std::size_t k = 0; k < sizes.size(); ++k)
        if (static_cast<int>(k) != main && sizes[k] > sliver) return false;
    bool changed = false;
    for (std::size_t i = 0; i < r.lab.size(); ++i)
        if (r.lab[i] == kFree && comp[i] != main)
        {
            r.lab[i] = kWall;
            changed = true;
        }
    if (changed)
    {
        cv::Mat mask(r.ny, r.nx, CV_8U);
        for (int i = 0; i < r.nx * r.ny; ++i) mask.data[i] = r.lab[i] == kFree ? 255 : 0;
        cv::distanceTransform(mask, r.dt, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    }
    return true;
}

// ---------------------------------------------------------------------------------------------
// Tour
// ---------------------------------------------------------------------------------------------

class TourBuilder
{
public:
    TourBuilder(const Plan& plan, const Raster& r) : m_plan(plan), m_r(r)
    {
        m_adj.resize(plan.spaces.size());
        for (std::size_t i = 0; i < plan.portals.size(); ++i)
        {
            m_adj[plan.portals[i].a].push_back(static_cast<int>(i));
            m_adj[plan.portals[i].b].push_back(static_cast<int>(i));
        }
    }

    /** The tour, or an empty vector when a space cannot be reached or a move is blocked. */
    std::vector<Vec> build()
    {
        m_visited.assign(m_plan.spaces.size(), false);
        m_used.assign(m_plan.portals.size(), false);
        m_ok = true;
        const Space& root = m_plan.spaces[0];
        const Vec start = root.visits.empty() ? centroid(root.poly) : root.visits.front();
        // The order: a depth-first walk of the space graph; the way from one task to the next
        // is the shortest through the graph (it retraces in trees and closes loops).
        m_tasks.clear();
        order(0, start);
        for (bool v : m_visited) m_ok = m_ok && v;
        m_tour = {start};
        m_space = 0;
        for (const Task& t : m_tasks)
        {
            if (!m_ok) break;
            travel(t.space, t.portal < 0 ? t.p : near(t.portal, t.space));
            if (t.portal >= 0) cross(t.portal);
        }
        travel(0, start);
        return m_ok ? m_tour : std::vector<Vec>{};
    }

private:
    struct Item
    {
        Vec p;
        int portal = -1;  // -1: a visit point
        double key = 0.0;
    };
    /** Reach point p in `space`, or cross `portal` out of `space`. */
    struct Task
    {
        int space = 0;
        int portal = -1;
        Vec p{0.0, 0.0};
    };

    /** Depth-first order of the tasks from `entry` in space `s`: visit points and every
     * portal, sorted along a corridor (nearer end first) or around a room or hall. */
    void order(int s, const Vec& entry)
    {
        m_visited[s] = true;
        const Space& sp = m_plan.spaces[s];
        std::vector<Item> items;
        for (int pi : m_adj[s])
        {
            if (m_used[pi]) continue;
            items.push_back({near(pi, s), pi, 0.0});
        }
        std::vector<Vec> visits = sp.visits;
        if (sp.kind == Kind::Room && items.empty())
        {
            // A room with one door: go 1 m in, towards its middle (the laser sees the rest).
            const Vec c = centroid(sp.poly);
            const double d = (c - entry).norm();
            visits.push_back(d > 1e-6 ? Vec(entry + (c - entry) * std::min(1.0, 1.0 / d)) : c);
        }
        for (const Vec& v : visits)
            if ((v - entry).norm() > 0.3) items.push_back({nudge(v), -1, 0.0});
        if (sp.kind == Kind::Corridor)
        {
            const double pe = sp.axis.dot(entry);
            double lo = 1e18, hi = -1e18;
            for (const Vec& v : sp.poly)
            {
                lo = std::min(lo, sp.axis.dot(v));
                hi = std::max(hi, sp.axis.dot(v));
            }
            const bool down_first = (pe - lo) < (hi - pe);
            for (Item& it : items)
            {
                const double q = sp.axis.dot(it.p) - pe;
                const bool first_side = down_first ? q <= 0 : q > 0;
                it.key = (first_side ? 0.0 : 1e6) + std::abs(q);
            }
        }
        else
        {
            const Vec c = centroid(sp.poly);
            const double a0 = std::atan2(entry.y() - c.y(), entry.x() - c.x());
            for (Item& it : items)
            {
                double a = std::atan2(it.p.y() - c.y(), it.p.x() - c.x()) - a0;
                while (a < 0) a += 2 * M_PI;
                while (a >= 2 * M_PI) a -= 2 * M_PI;
                it.key = a + 0.01 * (it.p - c).norm();
            }
        }
        std::stable_sort(items.begin(), items.end(),
                         [](const Item& a, const Item& b) { return a.key < b.key; });
        for (const Item& it : items)
        {
            if (it.portal < 0)
            {
                m_tasks.push_back({s, -1, it.p});
                continue;
            }
            if (m_used[it.portal]) continue;
            m_used[it.portal] = true;
            m_tasks.push_back({s, it.portal, it.p});
            const int other = this->other(it.portal, s);
            if (!m_visited[other]) order(other, near(it.portal, other));
        }
    }

    int other(int pi, int s) const
    {
        const Portal& d = m_plan.portals[pi];
        return d.a == s ? d.b : d.a;
    }

    /** Through a portal from the current space (the robot stands at its near point). */
    void cross(int pi)
    {
        const Portal& d = m_plan.portals[pi];
        const int to = other(pi, m_space);
        moveTo(near(pi, m_space));
        if (d.door)
        {
            push(d.c);
            push(near(pi, to));
        }
        m_space = to;
    }

    /** To point p of space `s` by the shortest way through the portals (Dijkstra over
     * (portal, space entered) states). */
    void travel(int s, const Vec& p)
    {
        if (!m_ok) return;
        if (s != m_space)
        {
            const std::size_t np = m_plan.portals.size();
            std::vector<double> dist(2 * np, 1e18);
            std::vector<int> prev(2 * np, -1);
            std::vector<bool> done(2 * np, false);
            auto state = [&](int pi, int space)
            { return 2 * pi + (m_plan.portals[pi].b == space); };
            auto relaxFrom = [&](int from_state, int space, const Vec& at, double base)
            {
                for (int pj : m_adj[space])
                {
                    if (from_state >= 0 && pj == from_state / 2) continue;
                    const int to = other(pj, space);
                    const int k = state(pj, to);
                    const double c = base + (at - near(pj, space)).norm() +
                                     (near(pj, space) - near(pj, to)).norm();
                    if (c < dist[k])
                    {
                        dist[k] = c;
                        prev[k] = from_state;
                    }
                }
            };
            relaxFrom(-1, m_space, m_tour.back(), 0.0);
            int best = -1;
            double best_cost = 1e18;
            for (;;)
            {
                int k = -1;
                for (std::size_t i = 0; i < 2 * np; ++i)
                    if (!done[i] && dist[i] < 1e17 && (k < 0 || dist[i] < dist[k]))
                        k = static_cast<int>(i);
                if (k < 0 || dist[k] >= best_cost) break;
                done[k] = true;
                const Portal& d = m_plan.portals[k / 2];
                const int space = (k % 2) ? d.b : d.a;
                const Vec at = near(k / 2, space);
                if (space == s && dist[k] + (at - p).norm() < best_cost)
                {
                    best_cost = dist[k] + (at - p).norm();
                    best = k;
                }
                relaxFrom(k, space, at, dist[k]);
            }
            if (best < 0)
            {
                m_ok = false;
                return;
            }
            std::vector<int> path;
            for (int k = best; k >= 0; k = prev[k]) path.push_back(k / 2);
            for (auto it = path.rbegin(); it != path.rend(); ++it) cross(*it);
        }
        moveTo(p);
    }

    /** The tour point on `s`'s side of a portal. */
    Vec near(int pi, int s) const
    {
        const Portal& d = m_plan.portals[pi];
        if (!d.door) return d.c;
        const double side = d.b == s ? 1.0 : -1.0;
        return d.c + side * (0.5 * m_plan.wall_m + kApproach) * d.n;
    }

    void push(const Vec& p)
    {
        if ((p - m_tour.back()).norm() > 1e-9) m_tour.push_back(p);
    }

    /** Straight when clear, else around obstacles. */
    void moveTo(const Vec& p)
    {
        const Vec a = m_tour.back();
        if ((p - a).norm() < 1e-9) return;
        if (m_r.segmentClearance(a, p, kPlanClearance) >= kPlanClearance)
        {
            push(p);
            return;
        }
        const std::vector<Vec> path = plan(a, p);
        if (path.empty())
        {
            m_ok = false;
            return;
        }
        for (const Vec& q : path) push(q);
    }

    /** A point near `p` with room around it (visit points in halls may sit on a column). */
    Vec nudge(const Vec& p) const
    {
        const double need = 0.7;
        if (m_r.clearance(p, need) >= need) return p;
        const int cx = static_cast<int>(std::floor((p.x() - m_r.x0) / m_r.res));
        const int cy = static_cast<int>(std::floor((p.y() - m_r.y0) / m_r.res));
        const int max_r = static_cast<int>(3.0 / m_r.res);
        for (int rr = 1; rr <= max_r; ++rr)
            for (int y = cy - rr; y <= cy + rr; ++y)
                for (int x = cx - rr; x <= cx + rr; ++x)
                {
                    if (std::max(std::abs(x - cx), std::abs(y - cy)) != rr || !m_r.free(x, y))
                        continue;
                    if (m_r.dt.at<float>(y, x) * m_r.res >= need + 2 * m_r.res)
                        return m_r.centre(x, y);
                }
        return p;
    }

    /** Grid search (A*) through cells far enough from obstacles, then shortcut. */
    std::vector<Vec> plan(const Vec& a, const Vec& b) const
    {
        const int nx = m_r.nx, ny = m_r.ny;
        auto cell = [&](const Vec& p)
        {
            const int cx =
                std::clamp(static_cast<int>(std::floor((p.x() - m_r.x0) / m_r.res)), 0, nx - 1);
            const int cy =
                std::clamp(static_cast<int>(std::floor((p.y() - m_r.y0) / m_r.res)), 0, ny - 1);
            return cy * nx + cx;
        };
        const int s = cell(a), g = cell(b);
        const float need = static_cast<float>((kPlanClearance + 1.6 * m_r.res) / m_r.res);
        std::vector<float> cost(nx * ny, std::numeric_limits<float>::infinity());
        std::vector<int> parent(nx * ny, -1);
        using QE = std::pair<float, int>;
        std::priority_queue<QE, std::vector<QE>, std::greater<QE>> open;
        const int gx = g % nx, gy = g / nx;
        auto h = [&](int i) { return std::hypot(float(i % nx - gx), float(i / nx - gy)); };
        cost[s] = 0.0f;
        open.push({h(s), s});
        const int dx[8] = {1, -1, 0, 0, 1, 1, -1, -1}, dy[8] = {0, 0, 1, -1, 1, -1, 1, -1};
        while (!open.empty())
        {
            const auto [f, i] = open.top();
            open.pop();
            if (i == g) break;
            if (f - h(i) > cost[i] + 1e-3f) continue;
            const int x = i % nx, y = i / nx;
            for (int k = 0; k < 8; ++k)
            {
                const int xx = x + dx[k], yy = y + dy[k];
                if (xx < 0 || yy < 0 || xx >= nx || yy >= ny) continue;
                const int j = yy * nx + xx;
                const float d = m_r.dt.at<float>(yy, xx);
                if (j != g && d < need) continue;
                const float step = (k < 4 ? 1.0f : 1.41421356f) * (1.0f + 8.0f / (d + 1.0f));
                if (cost[i] + step < cost[j])
                {
                    cost[j] = cost[i] + step;
                    parent[j] = i;
                    open.push({cost[j] + h(j), j});
                }
            }
        }
        if (parent[g] < 0) return {};
        std::vector<Vec> raw = {b};
        for (int i = parent[g]; i >= 0 && i != s; i = parent[i])
            raw.push_back(m_r.centre(i % nx, i / nx));
        raw.push_back(a);
        std::reverse(raw.begin(), raw.end());
        // Shortcut: from each kept point, the farthest point still in clear view.
        std::vector<Vec> out;
        std::size_t i = 0;
        while (i + 1 < raw.size())
        {
            std::size_t j = i + 1;
            while (j + 1 < raw.size() &&
                   m_r.segmentClearance(raw[i], raw[j + 1], kPlanClearance) >= kPlanClearance)
                ++j;
            out.push_back(raw[j]);
            i = j;
        }
        return out;
    }

    const Plan& m_plan;
    const Raster& m_r;
    std::vector<std::vector<int>> m_adj;
    std::vector<bool> m_visited, m_used;
    std::vector<Task> m_tasks;
    std::vector<Vec> m_tour;
    int m_space = 0;
    bool m_ok = true;
};

using Layout = void (*)(Plan&);

/** What a building is made of (for the corpus log). */
struct PlanStats
{
    int corridors = 0, rooms = 0, halls = 0, doors = 0, columns = 0, attempts = 0;
};

/** One attempt: layout, grid, checks, tour. False when any check fails. */
bool attempt(Layout layout, std::mt19937& rng, double res, Building& out, PlanStats* stats)
{
    Plan plan;
    plan.rng = &rng;
    plan.res = res;
    layout(plan);
    if (plan.spaces.size() < 4) return false;
    // Spaces not joined by an opening must keep a wall between them.
    const std::size_t ns = plan.spaces.size();
    std::vector<bool> joined(ns * ns, false);
    for (const Portal& d : plan.portals)
        if (!d.door) joined[d.a * ns + d.b] = joined[d.b * ns + d.a] = true;
    for (std::size_t i = 0; i < ns; ++i)
        for (std::size_t j = i + 1; j < ns; ++j)
            if (!joined[i * ns + j] &&
                gapBetween(plan.spaces[i].poly, plan.spaces[j].poly) < plan.wall_m - 1e-6)
                return false;
    double xmin = 1e18, ymin = 1e18, xmax = -1e18, ymax = -1e18;
    for (const Space& s : plan.spaces)
        for (const Vec& v : s.poly)
        {
            xmin = std::min(xmin, v.x());
            xmax = std::max(xmax, v.x());
            ymin = std::min(ymin, v.y());
            ymax = std::max(ymax, v.y());
        }
    const double w = xmax - xmin, h = ymax - ymin;
    if (std::max(w, h) > plan.max_extent_m || std::max(w, h) < plan.min_extent_m ||
        std::min(w, h) < plan.min_width_m)
        return false;
    const double margin = plan.wall_m + 1.0;
    const double gx0 = res * std::floor((xmin - margin) / res);
    const double gy0 = res * std::floor((ymin - margin) / res);
    const int nx = static_cast<int>(std::ceil((xmax + margin - gx0) / res));
    const int ny = static_cast<int>(std::ceil((ymax + margin - gy0) / res));
    out.grid.setSize(static_cast<float>(gx0), static_cast<float>(gx0 + nx * res),
                     static_cast<float>(gy0), static_cast<float>(gy0 + ny * res),
                     static_cast<float>(res), 0.5f);
    Raster r = rasterise(plan, out.grid);
    if (!enforceConnected(r)) return false;
    TourBuilder tb(plan, r);
    std::vector<Vec> tour = tb.build();
    if (tour.size() < 2) return false;
    for (std::size_t i = 0; i + 1 < tour.size(); ++i)
        if (r.segmentClearance(tour[i], tour[i + 1], kTourClearance) < kTourClearance) return false;
    for (int cy = 0; cy < r.ny; ++cy)
        for (int cx = 0; cx < r.nx; ++cx)
        {
            const std::uint8_t v = r.lab[cy * r.nx + cx];
            if (v != kUnknown) out.grid.setCell(cx, cy, v == kFree ? 1.0f : 0.0f);
        }
    out.tour.assign(tour.begin(), tour.end());
    if (stats)
    {
        for (const Space& sp : plan.spaces)
        {
            stats->corridors += sp.kind == Kind::Corridor;
            stats->rooms += sp.kind == Kind::Room;
            stats->halls += sp.kind == Kind::Hall;
        }
        for (const Portal& d : plan.portals) stats->doors += d.door;
        stats->columns = static_cast<int>(plan.columns.size());
    }
    return true;
}

Building makeBuildingImpl(const std::string& style, std::uint32_t seed, double resolution_m,
                          PlanStats* stats)
{
    const std::vector<std::string> styles = allStyles();
    const auto it = std::find(styles.begin(), styles.end(), style);
    if (it == styles.end())
        throw std::invalid_argument("makeBuilding: unknown style '" + style + "'");
    if (!(resolution_m >= 0.01 && resolution_m <= 0.2))
        throw std::invalid_argument("makeBuilding: resolution_m = " + std::to_string(resolution_m) +
                                    " outside [0.01, 0.2]");
    const std::size_t index = static_cast<std::size_t>(it - styles.begin());
    const Layout layouts[] = {layoutCorridorOffice, layoutColumnHall, layoutAngled, layoutMultiWing,
                              layoutRing,           layoutWarehouse,  layoutHouse};
    if (index >= std::size(layouts))
        throw std::logic_error("makeBuilding: no layout for style '" + style + "'");
    std::seed_seq seq{static_cast<std::uint32_t>(index), seed, 0x7b1du};
    std::mt19937 rng(seq);
    Building b;
    b.style = style;
    b.seed = seed;
    b.name = style + "_" + std::to_string(seed);
    for (int i = 0; i < 40; ++i)
        if (attempt(layouts[index], rng, resolution_m, b, stats))
        {
            if (stats) stats->attempts = i + 1;
            return b;
        }
    throw std::runtime_error("makeBuilding: no valid layout for " + b.name + " in 40 attempts");
}
}  // namespace

std::vector<std::string> buildingStyles()
{
    return {"corridor_office", "column_hall", "angled", "multi_wing"};
}

std::vector<std::string> heldOutStyles() { return {"ring", "warehouse", "house"}; }

std::vector<std::string> allStyles()
{
    std::vector<std::string> all = buildingStyles();
    for (const std::string& h : heldOutStyles()) all.push_back(h);
    return all;
}

Building makeBuilding(const std::string& style, std::uint32_t seed, double resolution_m)
{
    return makeBuildingImpl(style, seed, resolution_m, nullptr);
}
}  // namespace mrpt_topoeval::validation
