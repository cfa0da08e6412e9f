// CSV and hand-written SVG plots (report.h).
#include "report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace clothtear::bench {

Csv::Csv(const std::string& path, const std::vector<std::string>& header) : out_(path) {
    for (size_t i = 0; i < header.size(); ++i)
        out_ << (i ? "," : "") << header[i];
    out_ << "\n";
}

double logLogSlope(const std::vector<std::pair<double, double>>& points) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (const auto& [x, y] : points) {
        if (!(x > 0) || !(y > 0))
            continue;
        const double lx = std::log(x), ly = std::log(y);
        sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
        ++n;
    }
    if (n < 2)
        return std::numeric_limits<double>::quiet_NaN();
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

namespace {

const char* kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                         "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};

std::string escape(const std::string& s) {
    std::string o;
    for (char c : s) {
        if (c == '<')
            o += "&lt;";
        else if (c == '>')
            o += "&gt;";
        else if (c == '&')
            o += "&amp;";
        else
            o += c;
    }
    return o;
}

std::string num(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.4g", v);
    return b;
}

// One axis: data range to pixels, with ticks at decades (log) or at 1-2-5 steps (linear).
struct Axis {
    bool log;
    double lo, hi; // in data units (log: positive)
    double p0, p1; // pixels
    double map(double v) const {
        const double t =
            log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)) : (v - lo) / (hi - lo);
        return p0 + t * (p1 - p0);
    }
    std::vector<double> ticks() const {
        std::vector<double> t;
        if (log) {
            for (double d = std::pow(10, std::floor(std::log10(lo))); d <= hi * 1.0001; d *= 10)
                if (d >= lo * 0.9999)
                    t.push_back(d);
        } else {
            const double span = hi - lo, raw = span / 6, mag = std::pow(10, std::floor(std::log10(raw)));
            const double step = raw / mag < 2 ? 2 * mag : raw / mag < 5 ? 5 * mag : 10 * mag;
            for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * span; v += step)
                t.push_back(v);
        }
        return t;
    }
};

Axis makeAxis(bool log, std::vector<double> values, double p0, double p1) {
    values.erase(std::remove_if(values.begin(), values.end(),
                                [&](double v) { return !std::isfinite(v) || (log && v <= 0); }),
                 values.end());
    if (values.empty())
        values = {1, 10};
    double lo = *std::min_element(values.begin(), values.end()),
           hi = *std::max_element(values.begin(), values.end());
    if (log) {
        lo = std::pow(10, std::floor(std::log10(lo)));
        hi = std::pow(10, std::ceil(std::log10(hi)));
        if (hi <= lo)
            hi = lo * 10;
    } else {
        const double pad = hi > lo ? 0.05 * (hi - lo) : std::max(1.0, std::abs(lo) * 0.1);
        lo -= pad, hi += pad;
    }
    return Axis{log, lo, hi, p0, p1};
}

} // namespace

bool writeSvg(const Plot& plot, const std::string& path) {
    const double W = 760, H = 500, left = 80, right = 210, top = 40, bottom = 60;
    const double noteH = 16.0 * double(plot.notes.size());
    std::vector<double> xs, ys;
    for (const Series& s : plot.series)
        for (const auto& [x, y] : s.points)
            xs.push_back(x), ys.push_back(y);
    const Axis ax = makeAxis(plot.logX, xs, left, W - right);
    const Axis ay = makeAxis(plot.logY, ys, H - bottom, top);
    std::ostringstream o;
    o << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W << "' height='" << H + noteH
      << "' font-family='sans-serif' font-size='12'>\n";
    o << "<rect width='100%' height='100%' fill='white'/>\n";
    o << "<text x='" << W / 2 << "' y='22' text-anchor='middle' font-size='15'>" << escape(plot.title)
      << "</text>\n";
    // Grid and ticks.
    for (double t : ax.ticks()) {
        const double px = ax.map(t);
        o << "<line x1='" << px << "' y1='" << top << "' x2='" << px << "' y2='" << H - bottom
          << "' stroke='#ddd'/>\n";
        o << "<text x='" << px << "' y='" << H - bottom + 16 << "' text-anchor='middle'>" << num(t)
          << "</text>\n";
    }
    for (double t : ay.ticks()) {
        const double py = ay.map(t);
        o << "<line x1='" << left << "' y1='" << py << "' x2='" << W - right << "' y2='" << py
          << "' stroke='#ddd'/>\n";
        o << "<text x='" << left - 6 << "' y='" << py + 4 << "' text-anchor='end'>" << num(t) << "</text>\n";
    }
    o << "<rect x='" << left << "' y='" << top << "' width='" << W - right - left << "' height='"
      << H - bottom - top << "' fill='none' stroke='black'/>\n";
    o << "<text x='" << (left + W - right) / 2 << "' y='" << H - 18 << "' text-anchor='middle'>"
      << escape(plot.xLabel) << (plot.logX ? " (log)" : "") << "</text>\n";
    o << "<text transform='translate(18," << (top + H - bottom) / 2 << ") rotate(-90)' text-anchor='middle'>"
      << escape(plot.yLabel) << (plot.logY ? " (log)" : "") << "</text>\n";
    // Series.
    for (size_t i = 0; i < plot.series.size(); ++i) {
        const Series& s = plot.series[i];
        const char* color = kColors[i % (sizeof kColors / sizeof *kColors)];
        std::vector<std::pair<double, double>> pts;
        for (const auto& [x, y] : s.points)
            if (std::isfinite(x) && std::isfinite(y) && (!plot.logX || x > 0) && (!plot.logY || y > 0))
                pts.emplace_back(ax.map(x), ay.map(y));
        if (!s.markersOnly && pts.size() > 1) {
            o << "<polyline fill='none' stroke='" << color << "' stroke-width='1.8'"
              << (s.dashed ? " stroke-dasharray='6,4'" : "") << " points='";
            for (const auto& [px, py] : pts)
                o << px << "," << py << " ";
            o << "'/>\n";
        }
        for (const auto& [px, py] : pts)
            o << "<circle cx='" << px << "' cy='" << py << "' r='3' fill='" << color << "'/>\n";
        const double ly = top + 10 + 18.0 * double(i);
        o << "<line x1='" << W - right + 12 << "' y1='" << ly << "' x2='" << W - right + 36 << "' y2='" << ly
          << "' stroke='" << color << "' stroke-width='2'" << (s.dashed ? " stroke-dasharray='6,4'" : "")
          << "/>\n";
        o << "<text x='" << W - right + 42 << "' y='" << ly + 4 << "'>" << escape(s.name) << "</text>\n";
    }
    for (size_t i = 0; i < plot.notes.size(); ++i)
        o << "<text x='10' y='" << H + 12 + 16.0 * double(i) << "' font-size='11' fill='#444'>"
          << escape(plot.notes[i]) << "</text>\n";
    o << "</svg>\n";
    std::ofstream f(path);
    f << o.str();
    return bool(f);
}

} // namespace clothtear::bench
