// SPDX-License-Identifier: MIT
#include "tools/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "exporters/povray/pov_writer.h"

namespace rt::cli {

namespace {

bool drawable(double x, double y) { return x > 0 && y > 0 && std::isfinite(x) && std::isfinite(y); }

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    return buf;
}

std::string dashArray(Stroke s) {
    switch (s) {
        case Stroke::Dashed:
            return " stroke-dasharray=\"8 5\"";
        case Stroke::Dotted:
            return " stroke-dasharray=\"1.5 4\" stroke-linecap=\"round\"";
        case Stroke::Solid:
            break;
    }
    return "";
}

/// Decades covering [lo, hi] (both positive); a small tolerance keeps an exact power of ten
/// from adding a decade through rounding.
void decades(double lo, double hi, int &dLo, int &dHi) {
    dLo = static_cast<int>(std::floor(std::log10(lo) + 1e-9));
    dHi = static_cast<int>(std::ceil(std::log10(hi) - 1e-9));
    if (dHi <= dLo) dHi = dLo + 1;
}

}  // namespace

std::string xmlEscape(const std::string &text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&apos;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

std::string decadeLabel(int e) {
    if (e >= 0 && e <= 3) return "1" + std::string(e, '0');
    if (e < 0 && e >= -3) return "0." + std::string(-e - 1, '0') + "1";
    return "1e" + std::to_string(e);
}

LogLogFit fitLogLog(const std::vector<double> &x, const std::vector<double> &y) {
    LogLogFit fit;
    std::vector<double> lx, ly;
    for (size_t i = 0; i < std::min(x.size(), y.size()); ++i)
        if (drawable(x[i], y[i])) {
            lx.push_back(std::log10(x[i]));
            ly.push_back(std::log10(y[i]));
        }
    fit.points = static_cast<int>(lx.size());
    if (lx.size() < 2) return fit;
    double n = static_cast<double>(lx.size()), mx = 0, my = 0;
    for (size_t i = 0; i < lx.size(); ++i) {
        mx += lx[i];
        my += ly[i];
    }
    mx /= n;
    my /= n;
    double sxx = 0, sxy = 0;
    for (size_t i = 0; i < lx.size(); ++i) {
        sxx += (lx[i] - mx) * (lx[i] - mx);
        sxy += (lx[i] - mx) * (ly[i] - my);
    }
    // All x equal (to rounding): no slope
    if (!(sxx > 1e-20 * n)) return fit;
    fit.slope = sxy / sxx;
    fit.intercept = my - fit.slope * mx;
    fit.valid = std::isfinite(fit.slope) && std::isfinite(fit.intercept);
    return fit;
}

DecadeRange LogLogPlot::range() const {
    double inf = std::numeric_limits<double>::infinity();
    double xMin = inf, xMax = 0, yMin = inf, yMax = 0;
    for (const auto &s : series_)
        for (size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i)
            if (drawable(s.x[i], s.y[i])) {
                xMin = std::min(xMin, s.x[i]);
                xMax = std::max(xMax, s.x[i]);
                yMin = std::min(yMin, s.y[i]);
                yMax = std::max(yMax, s.y[i]);
            }
    DecadeRange r;
    if (xMax > 0) {
        decades(xMin, xMax, r.xLo, r.xHi);
        decades(yMin, yMax, r.yLo, r.yHi);
    }
    return r;
}

std::string LogLogPlot::svg() const {
    const DecadeRange r = range();
    const double left = 84, right = 24, top = 44, bottom = 58;
    const double px0 = left, px1 = width - right, py0 = top, py1 = height - bottom;
    auto X = [&](double lx) { return px0 + (lx - r.xLo) / (r.xHi - r.xLo) * (px1 - px0); };
    auto Y = [&](double ly) { return py1 - (ly - r.yLo) / (r.yHi - r.yLo) * (py1 - py0); };

    std::string o;
    o += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width) +
         "\" height=\"" + std::to_string(height) + "\" viewBox=\"0 0 " + std::to_string(width) +
         " " + std::to_string(height) + "\" font-family=\"sans-serif\" font-size=\"12\">\n";
    o += "<title>" + xmlEscape(title) + "</title>\n";
    o += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    o += "<defs><clipPath id=\"plot-area\"><rect x=\"" + num(px0) + "\" y=\"" + num(py0) +
         "\" width=\"" + num(px1 - px0) + "\" height=\"" + num(py1 - py0) +
         "\"/></clipPath></defs>\n";

    // Grid: decades darker than the 2..9 subdivisions
    std::string grid, ticks, labels;
    auto vertical = [&](double lx, bool major) {
        double x = X(lx);
        grid += "<line x1=\"" + num(x) + "\" y1=\"" + num(py0) + "\" x2=\"" + num(x) + "\" y2=\"" +
                num(py1) + "\" stroke=\"" + (major ? "#d8d8d8" : "#f0f0f0") + "\"/>\n";
        ticks += "<line x1=\"" + num(x) + "\" y1=\"" + num(py1) + "\" x2=\"" + num(x) + "\" y2=\"" +
                 num(py1 + (major ? 6 : 3)) + "\"/>\n";
    };
    auto horizontal = [&](double ly, bool major) {
        double y = Y(ly);
        grid += "<line x1=\"" + num(px0) + "\" y1=\"" + num(y) + "\" x2=\"" + num(px1) +
                "\" y2=\"" + num(y) + "\" stroke=\"" + (major ? "#d8d8d8" : "#f0f0f0") + "\"/>\n";
        ticks += "<line x1=\"" + num(px0 - (major ? 6 : 3)) + "\" y1=\"" + num(y) + "\" x2=\"" +
                 num(px0) + "\" y2=\"" + num(y) + "\"/>\n";
    };
    for (int e = r.xLo; e <= r.xHi; ++e) {
        vertical(e, true);
        labels += "<text class=\"tick-label\" x=\"" + num(X(e)) + "\" y=\"" + num(py1 + 20) +
                  "\" text-anchor=\"middle\">" + decadeLabel(e) + "</text>\n";
        if (e < r.xHi)
            for (int m = 2; m <= 9; ++m) vertical(e + std::log10(double(m)), false);
    }
    for (int e = r.yLo; e <= r.yHi; ++e) {
        horizontal(e, true);
        labels += "<text class=\"tick-label\" x=\"" + num(px0 - 9) + "\" y=\"" + num(Y(e) + 4) +
                  "\" text-anchor=\"end\">" + decadeLabel(e) + "</text>\n";
        if (e < r.yHi)
            for (int m = 2; m <= 9; ++m) horizontal(e + std::log10(double(m)), false);
    }
    o += "<g id=\"grid\">\n" + grid + "</g>\n";
    o += "<g id=\"ticks\" stroke=\"black\">\n" + ticks + "</g>\n";
    o += "<rect x=\"" + num(px0) + "\" y=\"" + num(py0) + "\" width=\"" + num(px1 - px0) +
         "\" height=\"" + num(py1 - py0) + "\" fill=\"none\" stroke=\"black\"/>\n";
    o += "<g id=\"tick-labels\">\n" + labels + "</g>\n";
    o += "<text x=\"" + num((px0 + px1) / 2) + "\" y=\"" + num(height - 14.0) +
         "\" text-anchor=\"middle\" font-size=\"13\">" + xmlEscape(xLabel) + "</text>\n";
    o += "<text x=\"18\" y=\"" + num((py0 + py1) / 2) +
         "\" text-anchor=\"middle\" font-size=\"13\" transform=\"rotate(-90 18 " +
         num((py0 + py1) / 2) + ")\">" + xmlEscape(yLabel) + "</text>\n";
    o += "<text x=\"" + num(width / 2.0) +
         "\" y=\"26\" text-anchor=\"middle\" font-size=\"15\" "
         "font-weight=\"bold\">" +
         xmlEscape(title) + "</text>\n";

    // Data, clipped to the plot area
    o += "<g clip-path=\"url(#plot-area)\" fill=\"none\" stroke-width=\"1.8\">\n";
    double lx0 = r.xLo, lx1 = r.xHi;
    for (const auto &l : lines_) {
        if (!drawable(l.x0, l.y0) || !std::isfinite(l.slope)) continue;
        auto ly = [&](double lx) { return std::log10(l.y0) + l.slope * (lx - std::log10(l.x0)); };
        o += "<line class=\"power-line\" x1=\"" + num(X(lx0)) + "\" y1=\"" + num(Y(ly(lx0))) +
             "\" x2=\"" + num(X(lx1)) + "\" y2=\"" + num(Y(ly(lx1))) + "\" stroke=\"" +
             xmlEscape(l.color) + "\"" + dashArray(l.stroke) + "/>\n";
    }
    for (const auto &s : series_) {
        std::string points, markers;
        for (size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
            if (!drawable(s.x[i], s.y[i])) continue;
            std::string px = num(X(std::log10(s.x[i]))), py = num(Y(std::log10(s.y[i])));
            points += (points.empty() ? "" : " ") + px + "," + py;
            if (s.markers) markers += "<circle cx=\"" + px + "\" cy=\"" + py + "\" r=\"3.5\"/>\n";
        }
        if (points.empty()) continue;
        o += "<polyline class=\"series\" points=\"" + points + "\" stroke=\"" + xmlEscape(s.color) +
             "\"" + dashArray(s.stroke) + "/>\n";
        if (!markers.empty())
            o += "<g fill=\"" + xmlEscape(s.color) + "\" stroke=\"none\">\n" + markers + "</g>\n";
    }
    o += "</g>\n";

    // Legend in the top right corner of the plot, where a falling error curve rarely goes
    struct Entry {
        std::string text, color;
        Stroke stroke;
        bool marker, swatch, bold;
    };
    std::vector<Entry> entries;
    if (!legendTitle.empty())
        entries.push_back({legendTitle, "", Stroke::Solid, false, false, true});
    for (const auto &s : series_)
        entries.push_back({s.label, s.color, s.stroke, s.markers, true, false});
    for (const auto &l : lines_)
        entries.push_back({l.label, l.color, l.stroke, false, true, false});
    for (const auto &n : notes_) entries.push_back({n, "", Stroke::Solid, false, false, false});
    if (!entries.empty()) {
        const double lineHeight = 18, swatch = 30, pad = 8;
        double textWidth = 0;
        for (const auto &e : entries)
            textWidth = std::max(textWidth, 6.8 * e.text.size() + (e.swatch ? swatch + 6 : 0));
        double boxW = textWidth + 2 * pad, boxH = lineHeight * entries.size() + pad;
        double bx = std::max(px0 + 4, px1 - 8 - boxW), by = py0 + 8;
        o += "<g id=\"legend\">\n<rect x=\"" + num(bx) + "\" y=\"" + num(by) + "\" width=\"" +
             num(boxW) + "\" height=\"" + num(boxH) +
             "\" fill=\"white\" fill-opacity=\"0.9\" stroke=\"#999999\"/>\n";
        for (size_t i = 0; i < entries.size(); ++i) {
            const Entry &e = entries[i];
            double y = by + pad + lineHeight * i + lineHeight / 2;
            double tx = bx + pad;
            if (e.swatch) {
                o += "<line x1=\"" + num(tx) + "\" y1=\"" + num(y) + "\" x2=\"" + num(tx + swatch) +
                     "\" y2=\"" + num(y) + "\" stroke=\"" + xmlEscape(e.color) +
                     "\" stroke-width=\"1.8\"" + dashArray(e.stroke) + "/>\n";
                if (e.marker)
                    o += "<circle cx=\"" + num(tx + swatch / 2) + "\" cy=\"" + num(y) +
                         "\" r=\"3.5\" fill=\"" + xmlEscape(e.color) + "\"/>\n";
                tx += swatch + 6;
            }
            o += "<text x=\"" + num(tx) + "\" y=\"" + num(y + 4) + "\"" +
                 (e.bold ? " font-weight=\"bold\"" : "") + ">" + xmlEscape(e.text) + "</text>\n";
        }
        o += "</g>\n";
    }
    o += "</svg>\n";
    return o;
}

void LogLogPlot::write(const std::string &path) const { pov::writeTextFile(path, svg()); }

}  // namespace rt::cli
