/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// scores.png: the scores of the snapshots against time, drawn with OpenCV (no plotting
// dependency): one polyline with markers per score, axes with ticks, a legend on the right.

#include <mrpt_topoeval/scores/scores.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

namespace mrpt_topoeval
{
namespace
{
constexpr int kWidth = 960, kHeight = 540;
constexpr int kLeft = 70, kRight = 210, kTop = 50, kBottom = 60;
const cv::Scalar kWhite(255, 255, 255), kBlack(0, 0, 0), kGrid(225, 225, 225);
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;

/** A tick step of 1, 2 or 5 times a power of ten giving about `target` ticks over `span`. */
double niceStep(double span, int target)
{
    if (!(span > 0.0)) return 1.0;
    const double raw = span / target;
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    for (const double m : {1.0, 2.0, 5.0, 10.0})
        if (raw <= m * p) return m * p;
    return 10.0 * p;
}

std::string tickLabel(double v, double step)
{
    char buf[32];
    if (step >= 1.0)
        std::snprintf(buf, sizeof(buf), "%.0f", v);
    else
        std::snprintf(buf, sizeof(buf), "%.*f", static_cast<int>(std::ceil(-std::log10(step))), v);
    return buf;
}

void putText(cv::Mat& img, const std::string& text, cv::Point at, double scale = 0.45,
             const cv::Scalar& colour = kBlack, int thickness = 1)
{
    cv::putText(img, text, at, kFont, scale, colour, thickness, cv::LINE_AA);
}

int textWidth(const std::string& text, double scale = 0.45)
{
    int base = 0;
    return cv::getTextSize(text, kFont, scale, 1, &base).width;
}

struct Series
{
    const char* name;
    cv::Scalar colour;  // BGR
    double ScoreRow::*value;
    int thickness;
};
}  // namespace

mrpt::img::CImage drawScorePlot(const std::vector<ScoreRow>& rows, const std::string& title)
{
    cv::Mat img(kHeight, kWidth, CV_8UC3, kWhite);
    const int x0 = kLeft, x1 = kWidth - kRight, y0 = kHeight - kBottom, y1 = kTop;

    // Time when every row has one; the entry number otherwise (maps saved by other systems).
    const bool by_time =
        !rows.empty() && std::all_of(rows.begin(), rows.end(),
                                     [](const auto& r) { return std::isfinite(r.time_s); });
    auto xOf = [&](const ScoreRow& r) { return by_time ? r.time_s : static_cast<double>(r.entry); };
    double xmin = 0.0, xmax = 1.0;
    if (!rows.empty())
    {
        xmin = xmax = xOf(rows.front());
        for (const auto& r : rows)
        {
            xmin = std::min(xmin, xOf(r));
            xmax = std::max(xmax, xOf(r));
        }
        xmin = std::min(xmin, 0.0);
        if (xmax - xmin < 1e-9) xmax = xmin + 1.0;
    }
    auto px = [&](double x)
    { return x0 + static_cast<int>(std::lround((x - xmin) / (xmax - xmin) * (x1 - x0))); };
    auto py = [&](double y)
    { return y0 - static_cast<int>(std::lround(std::clamp(y, 0.0, 1.0) * (y0 - y1))); };

    // Grid lines and ticks.
    for (int i = 0; i <= 10; ++i)
    {
        const double y = i / 10.0;
        cv::line(img, {x0, py(y)}, {x1, py(y)}, kGrid, 1);
        if (i % 2 == 0)
        {
            const std::string lab = tickLabel(y, 0.1);
            putText(img, lab, {x0 - 8 - textWidth(lab), py(y) + 5});
        }
    }
    const double xstep = niceStep(xmax - xmin, 8);
    for (double x = std::ceil(xmin / xstep) * xstep; x <= xmax + 1e-9 * xstep; x += xstep)
    {
        cv::line(img, {px(x), y0}, {px(x), y1}, kGrid, 1);
        cv::line(img, {px(x), y0}, {px(x), y0 + 5}, kBlack, 1);
        const std::string lab = tickLabel(x, xstep);
        putText(img, lab, {px(x) - textWidth(lab) / 2, y0 + 20});
    }
    cv::rectangle(img, {x0, y1}, {x1, y0}, kBlack, 1);
    const std::string xlabel = by_time ? "time [s]" : "entry";
    putText(img, xlabel, {(x0 + x1 - textWidth(xlabel)) / 2, y0 + 45});
    putText(img, "score", {8, y1 - 12});
    putText(img, title, {x0, 30}, 0.6, kBlack, 1);

    static const std::vector<Series> kSeries = {
        {"quality", cv::Scalar(0, 0, 0), &ScoreRow::quality, 3},
        {"coverage", cv::Scalar(200, 90, 20), &ScoreRow::coverage, 2},
        {"relative accuracy", cv::Scalar(30, 30, 220), &ScoreRow::relative_accuracy, 2},
        {"consistency short", cv::Scalar(40, 160, 40), &ScoreRow::consistency_short, 1},
        {"consistency medium", cv::Scalar(0, 140, 230), &ScoreRow::consistency_medium, 1},
        {"consistency long", cv::Scalar(170, 40, 170), &ScoreRow::consistency_long, 1},
        {"explained walls", cv::Scalar(0, 0, 255), &ScoreRow::explained_walls, 1},
    };
    for (const auto& s : kSeries)
    {
        std::vector<cv::Point> pts;
        for (const auto& r : rows) pts.emplace_back(px(xOf(r)), py(r.*s.value));
        if (pts.size() > 1) cv::polylines(img, pts, false, s.colour, s.thickness, cv::LINE_AA);
        for (const auto& p : pts) cv::circle(img, p, 3, s.colour, cv::FILLED, cv::LINE_AA);
    }

    // Legend, right of the plot.
    int ly = y1 + 10;
    for (const auto& s : kSeries)
    {
        cv::line(img, {x1 + 15, ly}, {x1 + 45, ly}, s.colour, s.thickness + 1, cv::LINE_AA);
        cv::circle(img, {x1 + 30, ly}, 3, s.colour, cv::FILLED, cv::LINE_AA);
        putText(img, s.name, {x1 + 52, ly + 5});
        ly += 24;
    }
    if (!rows.empty())
    {
        const ScoreRow& last = rows.back();
        char buf[64];
        ly += 12;
        putText(img, "last snapshot:", {x1 + 15, ly});
        std::snprintf(buf, sizeof(buf), "quality %.3f", last.quality);
        putText(img, buf, {x1 + 15, ly += 20});
        std::snprintf(buf, sizeof(buf), "coverage %.3f", last.coverage);
        putText(img, buf, {x1 + 15, ly += 20});
        std::snprintf(buf, sizeof(buf), "brokenness %d", last.brokenness);
        putText(img, buf, {x1 + 15, ly += 20});
        std::snprintf(buf, sizeof(buf), "%zu snapshots", rows.size());
        putText(img, buf, {x1 + 15, ly += 20});
    }
    else
        putText(img, "no snapshot", {x1 + 15, ly + 12});
    return mrpt::img::CImage(img, mrpt::img::DEEP_COPY);
}

}  // namespace mrpt_topoeval
