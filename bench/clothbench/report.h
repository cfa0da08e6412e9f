// Output of clothbench: CSV files and SVG plots written by hand (no plotting library on the
// machines), into the output folder given with --out.
#pragma once
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace clothtear::bench {

// A CSV file with a header row; values are written with full precision.
class Csv {
  public:
    Csv(const std::string& path, const std::vector<std::string>& header);
    bool ok() const { return bool(out_); }
    template <class... T> void row(const T&... values) {
        std::ostringstream line;
        line.precision(9);
        int i = 0;
        ((line << (i++ ? "," : ""), put(line, values)), ...);
        out_ << line.str() << "\n";
        out_.flush();
    }

  private:
    template <class V> static void put(std::ostringstream& o, const V& v) { o << v; }
    // Text with a comma or a quote is quoted (RFC 4180).
    static void put(std::ostringstream& o, const std::string& v) {
        if (v.find_first_of(",\"") == std::string::npos) {
            o << v;
            return;
        }
        o << '"';
        for (char c : v)
            o << (c == '"' ? "\"\"" : std::string(1, c));
        o << '"';
    }
    static void put(std::ostringstream& o, const char* v) { put(o, std::string(v)); }
    std::ofstream out_;
};

struct Series {
    std::string name;
    std::vector<std::pair<double, double>> points; // (x, y); non-positive values are skipped on log axes
    bool dashed = false;
    bool markersOnly = false;
};

struct Plot {
    std::string title, xLabel, yLabel;
    bool logX = true, logY = true;
    std::vector<Series> series;
    std::vector<std::string> notes; // lines printed under the plot (commands, caveats)
};

// Renders the plot as a standalone SVG document and writes it to `path`. False if not writable.
bool writeSvg(const Plot& plot, const std::string& path);

// Least-squares slope of log(y) against log(x) over the points given (the convergence order when
// x is dt and y the error). NaN with fewer than two points.
double logLogSlope(const std::vector<std::pair<double, double>>& points);

} // namespace clothtear::bench
