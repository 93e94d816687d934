// SPDX-License-Identifier: MIT
// A small log-log line plot written as SVG by hand (no dependencies), and the least-squares
// slope of a log-log relation: what `scadray converge` draws and fits.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace rt::cli {

enum class Stroke { Solid, Dashed, Dotted };

/// Points joined by lines; pairs with a non-positive coordinate cannot be shown on log axes and
/// are left out.
struct PlotSeries {
    std::string label;
    std::string color = "#1f77b4";
    std::vector<double> x, y;
    Stroke stroke = Stroke::Solid;
    bool markers = true;
};

/// The straight line y = y0 * (x / x0)^slope across the whole plot (a power law); it does not
/// widen the axes.
struct PlotLine {
    std::string label;
    std::string color = "#555555";
    double slope = 0, x0 = 1, y0 = 1;
    Stroke stroke = Stroke::Dashed;
};

/// Axis ranges in whole decades: [10^xLo, 10^xHi] and [10^yLo, 10^yHi], lo < hi.
struct DecadeRange {
    int xLo = 0, xHi = 1, yLo = 0, yHi = 1;
};

/// A log-log plot: series, power-law lines, a legend (title, one entry per series and line,
/// free notes) and axes with a tick and label at every decade, unlabelled ticks at 2..9.
class LogLogPlot {
  public:
    std::string title, xLabel, yLabel;
    /// First, bold line of the legend (e.g. the scene's name); none when empty.
    std::string legendTitle;
    int width = 720, height = 480;

    void addSeries(PlotSeries s) { series_.push_back(std::move(s)); }
    void addLine(PlotLine l) { lines_.push_back(std::move(l)); }
    /// A line of text in the legend, below the entries.
    void addNote(std::string text) { notes_.push_back(std::move(text)); }

    /// The decades covering every drawable point of every series (1 to 10 on an axis with none).
    DecadeRange range() const;
    /// The whole document, starting with `<svg`.
    std::string svg() const;
    /// Writes svg() to `path` through a temporary file and a rename.
    void write(const std::string &path) const;

  private:
    std::vector<PlotSeries> series_;
    std::vector<PlotLine> lines_;
    std::vector<std::string> notes_;
};

/// Least-squares fit of log10(y) = intercept + slope * log10(x) over the pairs with x > 0 and
/// y > 0 (finite). `valid` needs at least two such pairs with different x.
struct LogLogFit {
    bool valid = false;
    double slope = 0, intercept = 0;
    int points = 0;
};
LogLogFit fitLogLog(const std::vector<double> &x, const std::vector<double> &y);

/// 10^e as a tick label: "0.01", "1", "1000" for |e| <= 3, else "1e-5".
std::string decadeLabel(int exponent);

/// `text` with &, <, >, " and ' escaped for XML, and so for HTML5 text and attribute values too
/// (the report's page uses it).
std::string xmlEscape(const std::string &text);

}  // namespace rt::cli
