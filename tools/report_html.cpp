// SPDX-License-Identifier: MIT
// The HTML page of `scadray report`, written by hand: a small stylesheet, a sortable table,
// and Chart.js (embedded) for the log-log plots of converge.
#include "tools/report_html.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "core/system/input_file.h"
#include "tools/svg_plot.h"

namespace rt::cli {

namespace {

namespace fs = std::filesystem;

std::string fmt(const char *format, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

/// A number for a data-v attribute: full precision, sortable by the page's script.
std::string sortKey(double v) { return std::isfinite(v) ? fmt("%.17g", v) : ""; }

/// `text` as a JSON string literal that is also safe inside <script>: <, > and & escaped.
std::string jsonString(const std::string &text) {
    std::string out = "\"";
    for (unsigned char c : text) {
        switch (c) {
            case '"':
                out += "\\\"";
                break;
            case '\\':
                out += "\\\\";
                break;
            case '\n':
                out += "\\n";
                break;
            default:
                if (c < 0x20 || c == '<' || c == '>' || c == '&') {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", c);
                    out += buf;
                } else {
                    out += char(c);
                }
        }
    }
    return out + "\"";
}

std::string jsonNumber(double v) { return std::isfinite(v) ? fmt("%.9g", v) : "null"; }

const char *verdictName(int rank) {
    static const char *names[] = {"ERROR", "DIFFERENT", "PASS"};
    return names[std::clamp(rank, 0, 2)];
}
const char *verdictClass(int rank) {
    static const char *names[] = {"error", "different", "pass"};
    return names[std::clamp(rank, 0, 2)];
}
int checkRank(const CheckResult &r) { return !r.error.empty() ? 0 : r.pass ? 2 : 1; }

/// A table cell with its sort key; an empty key sorts last whichever the direction.
std::string cell(const std::string &text, const std::string &key, const char *cls = "num") {
    return "<td class=\"" + std::string(cls) + "\" data-v=\"" + xmlEscape(key) + "\">" + text +
           "</td>";
}
std::string emptyCell() { return "<td class=\"num\" data-v=\"\">&ndash;</td>"; }

/// The fitted slope of a converge curve (scadray against its reference), if it has one.
std::optional<double> convergeSlope(const ConvergeCurve &c) {
    LogLogFit fit = fitLogLog(c.seconds, c.rmse);
    if (!fit.valid) return std::nullopt;
    return fit.slope;
}

const char *kStyle = R"CSS(
body { font: 14px/1.4 system-ui, sans-serif; margin: 1.5em; color: #222; }
h1 { margin: 0 0 .2em; font-size: 1.6em; }
.meta { color: #666; font-size: .9em; }
.summary { display: flex; flex-wrap: wrap; gap: .8em; margin: 1em 0; }
.summary div { border: 1px solid #ccc; border-radius: 6px; padding: .5em .9em; min-width: 8em; }
.summary b { display: block; font-size: 1.5em; }
.summary .fail b { color: #b00020; } .summary .ok b { color: #1b7f2a; }
table { border-collapse: collapse; margin: 1em 0; }
th, td { border-bottom: 1px solid #ddd; padding: .25em .6em; }
th { cursor: pointer; background: #f3f3f3; position: sticky; top: 0; text-align: left;
     user-select: none; white-space: nowrap; }
th[aria-sort=ascending]::after { content: " \25B2"; }
th[aria-sort=descending]::after { content: " \25BC"; }
td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
.verdict { font-weight: bold; }
tr.error .verdict, section.error h2 .verdict { color: #b00020; }
tr.different .verdict, section.different h2 .verdict { color: #c25e00; }
tr.pass .verdict, section.pass h2 .verdict { color: #1b7f2a; }
section { border-top: 2px solid #ccc; margin-top: 2em; padding-top: .5em; }
section h2 { font-size: 1.15em; word-break: break-all; }
.pics { display: flex; flex-wrap: wrap; gap: .8em; }
figure { margin: 0; max-width: 32%; }
figure img { max-width: 100%; image-rendering: pixelated; border: 1px solid #ccc; }
.scroll { overflow-x: auto; }
a.top { font-size: .75em; font-weight: normal; margin-left: .8em; }
figure img.broken { outline: 3px solid #b00020; min-width: 4em; min-height: 3em; }
figcaption { font-size: .85em; color: #555; }
pre { background: #f7f7f7; padding: .6em; overflow-x: auto; font-size: .85em; }
pre.err { background: #fde8ec; }
.plot { max-width: 760px; }
#report-selfcheck { color: #666; font-size: .85em; }
)CSS";

const char *kScript = R"JS(
(function () {
  'use strict';
  // Sorting: a click sorts by the column (ascending, then descending); empty cells last,
  // ties in the original (failures-first) order
  const table = document.getElementById('scenes');
  const body = table.tBodies[0];
  let sortColumn = -1, sortDirection = 1;
  table.tHead.rows[0].querySelectorAll('th').forEach((th, i) => {
    th.addEventListener('click', () => {
      sortDirection = sortColumn === i ? -sortDirection : 1;
      sortColumn = i;
      table.tHead.querySelectorAll('th').forEach(h => h.removeAttribute('aria-sort'));
      th.setAttribute('aria-sort', sortDirection > 0 ? 'ascending' : 'descending');
      const rows = Array.from(body.rows);
      const key = r => r.cells[i].dataset.v || '';
      rows.sort((a, b) => {
        const x = key(a), y = key(b);
        if (x === '' || y === '') {
          if (x !== y) return x === '' ? 1 : -1;
        } else {
          const nx = Number(x), ny = Number(y);
          const c = !isNaN(nx) && !isNaN(ny) ? nx - ny : x.localeCompare(y);
          if (c !== 0) return sortDirection * c;
        }
        return a.dataset.order - b.dataset.order;
      });
      rows.forEach(r => body.appendChild(r));
    });
  });
  // A link may ask for an order: #sort=N (column N, from 0, ascending) or #sort=N-desc
  const asked = /^#sort=(\d+)(-desc)?$/.exec(location.hash);
  const headings = table.tHead.rows[0].cells;
  if (asked && +asked[1] < headings.length) {
    headings[+asked[1]].click();
    if (asked[2]) headings[+asked[1]].click();
  }

  // Plots of error against time, log-log
  let charts = 0;
  const curves = JSON.parse(document.getElementById('converge-data').textContent);
  for (const c of curves) {
    const canvas = document.getElementById(c.canvas);
    if (!window.Chart || !canvas) continue;
    const line = (label, color, points, extra) => Object.assign(
      {label: label, data: points, showLine: true, borderColor: color, backgroundColor: color},
      extra || {});
    const datasets = [line('scadray vs its converged reference', '#1f77b4', c.reference)];
    if (c.povray.length)
      datasets.push(line('scadray vs POV-Ray (' + c.supersample + 'x' + c.supersample +
                         ' supersampled)', '#d62728', c.povray));
    if (c.fit) datasets.push(line('least-squares fit: slope ' + c.fit.slope.toFixed(3),
                                  '#1f77b4', c.fit.points, {borderDash: [6, 4], pointRadius: 0}));
    const ys = c.reference.concat(c.povray).map(p => p.y).filter(y => y > 0);
    if (c.povraySeconds > 0 && ys.length)
      datasets.push(line('POV-Ray render time (' + c.povraySeconds.toPrecision(3) + ' s)',
                         '#2ca02c', [{x: c.povraySeconds, y: Math.min(...ys)},
                                     {x: c.povraySeconds, y: Math.max(...ys)}],
                         {borderDash: [2, 3], pointRadius: 0}));
    try {
      new Chart(canvas, {
        type: 'scatter',
        data: {datasets: datasets},
        options: {
          animation: false, responsive: false,
          scales: {
            x: {type: 'logarithmic', title: {display: true, text: 'render time (seconds)'}},
            y: {type: 'logarithmic', title: {display: true, text: 'RMSE (linear radiance)'}}
          },
          plugins: {
            title: {display: true, text: c.title},
            tooltip: {callbacks: {label: ctx => ctx.dataset.label + ': ' +
              (ctx.raw.spp ? ctx.raw.spp + ' spp, ' : '') + ctx.raw.x.toPrecision(3) +
              ' s, RMSE ' + ctx.raw.y.toPrecision(3)}}
          }
        }
      });
      charts++;
    } catch (e) {
      canvas.insertAdjacentText('afterend', 'plot failed: ' + e);
    }
  }

  // What a test (or a reader) needs to know: rows, their order, pictures that did not load
  const images = Array.from(document.images);
  Promise.all(images.map(img => img.complete ? null : new Promise(done => {
    img.addEventListener('load', done);
    img.addEventListener('error', done);
  }))).then(() => {
    const broken = images.filter(img => !(img.complete && img.naturalWidth > 0));
    broken.forEach(img => img.classList.add('broken'));
    const out = document.getElementById('report-selfcheck');
    out.dataset.rows = body.rows.length;
    out.dataset.verdicts = Array.from(body.rows).map(r => r.dataset.verdict).join(',');
    out.dataset.images = images.length;
    out.dataset.broken = broken.length;
    out.dataset.charts = charts;
    out.dataset.done = '1';
    out.textContent = (broken.length ? broken.length + ' of ' + images.length +
                       ' pictures did not load' : 'all ' + images.length + ' pictures loaded') +
                      ', ' + charts + ' plots drawn';
  });
})();
)JS";

/// The converge plot's data for the page's script.
std::string curveJson(const ReportScene &s, size_t index, const std::string &title) {
    const ConvergeCurve &c = *s.converge;
    auto points = [&](const std::vector<double> &y) {
        std::string out = "[";
        for (size_t i = 0; i < y.size() && i < c.seconds.size(); ++i) {
            // Log axes cannot show zero or negative values
            if (!(c.seconds[i] > 0) || !(y[i] > 0) || !std::isfinite(y[i])) continue;
            if (out.size() > 1) out += ",";
            out += "{\"x\":" + jsonNumber(c.seconds[i]) + ",\"y\":" + jsonNumber(y[i]) +
                   (i < c.samples.size() ? ",\"spp\":" + std::to_string(c.samples[i]) : "") + "}";
        }
        return out + "]";
    };
    std::string fit = "null";
    LogLogFit f = fitLogLog(c.seconds, c.rmse);
    if (f.valid) {
        double lo = *std::min_element(c.seconds.begin(), c.seconds.end());
        double hi = *std::max_element(c.seconds.begin(), c.seconds.end());
        auto at = [&](double x) { return std::pow(10.0, f.intercept + f.slope * std::log10(x)); };
        if (lo > 0 && hi > lo)
            fit = "{\"slope\":" + jsonNumber(f.slope) + ",\"points\":[{\"x\":" + jsonNumber(lo) +
                  ",\"y\":" + jsonNumber(at(lo)) + "},{\"x\":" + jsonNumber(hi) +
                  ",\"y\":" + jsonNumber(at(hi)) + "}]}";
    }
    double povSeconds = s.povray && s.povray->error.empty() ? s.povray->povraySeconds : 0;
    int supersample = s.povray ? s.povray->supersample : 0;
    return "{\"canvas\":\"plot-" + std::to_string(index) + "\",\"title\":" + jsonString(title) +
           ",\"reference\":" + points(c.rmse) + ",\"povray\":" + points(c.rmsePovray) +
           ",\"fit\":" + fit + ",\"povraySeconds\":" + jsonNumber(povSeconds) +
           ",\"supersample\":" + std::to_string(supersample) + "}";
}

/// Small pictures are shown at least this wide (magnified, pixels kept sharp), so a check
/// at 64x48 is still readable.
constexpr int kMinPictureWidth = 320;

std::string figure(const std::string &src, const std::string &caption, int width) {
    if (src.empty()) return "";
    return "<figure><img src=\"" + xmlEscape(src) + "\" alt=\"" + xmlEscape(caption) +
           "\" style=\"width: " + std::to_string(std::max(width, kMinPictureWidth)) +
           "px\"><figcaption>" + xmlEscape(caption) + "</figcaption></figure>";
}

std::string checkSection(const CheckResult &r, const PictureSources &pics) {
    std::string out;
    bool openscad = r.referee == "openscad";
    out += "<h3>" + std::string(openscad ? "OpenSCAD referee (geometry)" : "POV-Ray") + ": " +
           "<span class=\"verdict\">" + verdictName(checkRank(r)) + "</span></h3>\n";
    if (!r.error.empty()) return out + "<pre class=\"err\">" + xmlEscape(r.error) + "</pre>\n";
    std::string ss = std::to_string(r.supersample);
    out += "<div class=\"pics\">" +
           figure(pics[0],
                  openscad ? "OpenSCAD's mesh (normals)"
                           : "POV-Ray (" + ss + "x" + ss + " supersampled)",
                  r.width) +
           figure(pics[1], openscad ? "scadray (normals)" : "scadray", r.width) +
           figure(pics[2],
                  openscad ? "difference: red depth, yellow normal, magenta coverage, "
                             "blue masked"
                           : "difference: red-yellow error, blue masked, magenta "
                             "failed tiles",
                  r.width) +
           "</div>\n";
    out += "<pre>" + xmlEscape(r.text) + "</pre>\n";
    return out;
}

}  // namespace

int ReportScene::rank() const {
    int r = error.empty() ? 2 : 0;
    if (povray) r = std::min(r, checkRank(*povray));
    if (openscad) r = std::min(r, checkRank(*openscad));
    return r;
}

void sortFailuresFirst(std::vector<ReportScene> &scenes) {
    std::stable_sort(scenes.begin(), scenes.end(), [](const ReportScene &a, const ReportScene &b) {
        int ra = a.rank(), rb = b.rank();
        return ra != rb ? ra < rb : a.name() < b.name();
    });
}

namespace {

/// The CSV's text parsed; `path` names it in errors.
ConvergeCurve parseConvergeCsv(const std::string &path, const std::string &text) {
    std::istringstream in(text);
    std::string line;
    std::getline(in, line);
    if (line.rfind("samples,seconds,rmse,rmse_corrected", 0) != 0)
        throw std::runtime_error(path + ":1: not the CSV `scadray converge` writes");
    ConvergeCurve c;
    for (int number = 2; std::getline(in, line); ++number) {
        if (line.empty()) continue;
        std::vector<std::string> f;
        std::stringstream ss(line);
        for (std::string field; std::getline(ss, field, ',');) f.push_back(field);
        if (line.back() == ',') f.push_back("");
        if (f.size() < 6)
            throw std::runtime_error(path + ":" + std::to_string(number) +
                                     ": expected 6 fields, found " + std::to_string(f.size()));
        char *end = nullptr;
        c.samples.push_back(int(std::strtol(f[0].c_str(), &end, 10)));
        c.seconds.push_back(std::strtod(f[1].c_str(), &end));
        c.rmse.push_back(std::strtod(f[3].c_str(), &end));
        if (!f[5].empty()) c.rmsePovray.push_back(std::strtod(f[5].c_str(), &end));
    }
    if (!c.rmsePovray.empty() && c.rmsePovray.size() != c.seconds.size())
        throw std::runtime_error(path + ": rmse_povray is given on some rows only");
    return c;
}

}  // namespace

ConvergeCurve readConvergeCsv(const std::string &path) {
    return parseConvergeCsv(path, readInputFile(path, kMaxReportFileBytes));
}

ConvergeCurve readConvergeFiles(const std::string &folder, const std::string &stem) {
    std::string csv = stem + "_converge.csv", svg = stem + "_converge.svg";
    ConvergeCurve c = parseConvergeCsv((fs::path(folder) / csv).string(),
                                       readInputFileIn(folder, csv, kMaxReportFileBytes));
    std::error_code ec;
    if (fs::exists(fs::symlink_status(fs::path(folder) / svg, ec)))
        c.svg = readInputFileIn(folder, svg, kMaxReportFileBytes);
    return c;
}

std::string reportHtml(const ReportPage &page) {
    // Summary figures
    int counts[3] = {0, 0, 0};
    int oscadCounts[3] = {0, 0, 0};
    double povSeconds = 0, oursSeconds = 0, oscadSeconds = 0, oursGeometrySeconds = 0;
    bool anyOpenScad = false, anyConverge = false;
    for (const ReportScene &s : page.scenes) {
        ++counts[s.rank()];
        if (s.povray && s.povray->error.empty()) {
            povSeconds += s.povray->refereeSeconds();
            oursSeconds += s.povray->scadraySeconds;
        }
        if (s.openscad || !s.openscadNote.empty()) anyOpenScad = true;
        if (s.openscad) {
            ++oscadCounts[checkRank(*s.openscad)];
            if (s.openscad->error.empty()) {
                oscadSeconds += s.openscad->openscadSeconds;
                oursGeometrySeconds += s.openscad->scadraySeconds;
            }
        }
        anyConverge |= s.converge.has_value();
    }

    std::string h;
    h += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
    h += "<meta name=\"generator\" content=\"scadray report\">\n";
    h += "<title>" + xmlEscape(page.title) + "</title>\n<style>" + kStyle + "</style>\n";
    if (!page.chartJs.empty()) {
        // A "</script" inside the library would end the element early; the UMD build has
        // none, and any would be split so the page still parses
        std::string js = page.chartJs;
        for (size_t p = 0; (p = js.find("</script", p)) != std::string::npos; p += 9)
            js.replace(p, 8, "<\\/script");
        h += "<script>" + js + "\n</script>\n";
    }
    h += "</head>\n<body>\n";
    h += "<h1>" + xmlEscape(page.title) + "</h1>\n";
    h += "<div class=\"meta\">" + xmlEscape(page.generated) +
         (page.settings.empty() ? "" : " &middot; " + xmlEscape(page.settings)) + "</div>\n";

    // Summary
    int failed = counts[0] + counts[1];
    h += "<div class=\"summary\" id=\"summary\">";
    h += "<div class=\"" + std::string(failed ? "fail" : "ok") + "\"><b>" +
         std::to_string(counts[2]) + " / " + std::to_string(page.scenes.size()) +
         "</b>passed</div>";
    h += "<div class=\"" + std::string(counts[1] ? "fail" : "ok") + "\"><b>" +
         std::to_string(counts[1]) + "</b>different</div>";
    h += "<div class=\"" + std::string(counts[0] ? "fail" : "ok") + "\"><b>" +
         std::to_string(counts[0]) + "</b>errors</div>";
    h += "<div><b>" + fmt("%.1f s", page.wallSeconds) + "</b>report wall time</div>";
    if (oursSeconds > 0) {
        h += "<div><b>" + fmt("%.1f s", povSeconds) + " / " + fmt("%.2f s", oursSeconds) +
             "</b>POV-Ray / scadray, all scenes</div>";
        h += "<div><b>" + fmt("%.2f&times;", povSeconds / oursSeconds) +
             "</b>speed ratio (POV-Ray time &divide; scadray time)</div>";
    }
    if (anyOpenScad) {
        h += "<div><b>" + std::to_string(oscadCounts[2]) + " / " +
             std::to_string(oscadCounts[0] + oscadCounts[1] + oscadCounts[2]) +
             "</b>OpenSCAD referee passed</div>";
        if (oursGeometrySeconds > 0)
            h += "<div><b>" + fmt("%.1f s", oscadSeconds) + " / " +
                 fmt("%.2f s", oursGeometrySeconds) + "</b>OpenSCAD / scadray geometry</div>";
    }
    h += "</div>\n";

    // Table
    h += "<div class=\"scroll\"><table "
         "id=\"scenes\">\n<thead><tr><th>verdict</th><th>scene</th><th>RMSE</th>"
         "<th>max error</th><th>masked</th><th>tested</th><th>failed tiles</th>"
         "<th>POV-Ray s</th><th>scadray s</th><th>speed ratio</th>";
    if (anyOpenScad) h += "<th>OpenSCAD</th><th>differing px</th><th>OpenSCAD s</th>";
    if (anyConverge) h += "<th>converge slope</th>";
    h += "</tr></thead>\n<tbody>\n";
    for (size_t i = 0; i < page.scenes.size(); ++i) {
        const ReportScene &s = page.scenes[i];
        int rank = s.rank();
        h += "<tr class=\"" + std::string(verdictClass(rank)) + "\" data-order=\"" +
             std::to_string(i) + "\" data-verdict=\"" + verdictClass(rank) + "\">";
        h += cell(verdictName(rank), std::to_string(rank), "verdict");
        h += cell("<a href=\"#scene-" + std::to_string(i) + "\" title=\"" + xmlEscape(s.scene) +
                      "\">" + xmlEscape(s.name()) + "</a>",
                  s.name(), "name");
        const CheckResult *p = s.povray && s.povray->error.empty() ? &*s.povray : nullptr;
        if (p) {
            h += cell(fmt("%.3g", p->rmse), sortKey(p->rmse));
            h += cell(fmt("%.3g", p->maxError), sortKey(p->maxError));
            h += cell(fmt("%.1f%%", 100 * p->maskedShare), sortKey(p->maskedShare));
            h += cell(fmt("%.0f%%", 100 * p->testedShare), sortKey(p->testedShare));
            h += cell(std::to_string(p->tilesFailed), std::to_string(p->tilesFailed));
            h += cell(fmt("%.2f", p->refereeSeconds()), sortKey(p->refereeSeconds()));
            h += cell(fmt("%.2f", p->scadraySeconds), sortKey(p->scadraySeconds));
            double ratio = p->scadraySeconds > 0 ? p->refereeSeconds() / p->scadraySeconds : NAN;
            h += std::isfinite(ratio) ? cell(fmt("%.2f", ratio), sortKey(ratio)) : emptyCell();
        } else {
            for (int k = 0; k < 8; ++k) h += emptyCell();
        }
        if (anyOpenScad) {
            if (s.openscad) {
                int r = checkRank(*s.openscad);
                h += cell(verdictName(r), std::to_string(r), "verdict");
                if (s.openscad->error.empty()) {
                    h += cell(std::to_string(s.openscad->differing),
                              std::to_string(s.openscad->differing));
                    h += cell(fmt("%.2f", s.openscad->openscadSeconds),
                              sortKey(s.openscad->openscadSeconds));
                } else {
                    h += emptyCell() + emptyCell();
                }
            } else {
                h += cell("n/a", "", "name") + emptyCell() + emptyCell();
            }
        }
        if (anyConverge) {
            auto slope = s.converge ? convergeSlope(*s.converge) : std::nullopt;
            h += slope ? cell(fmt("%.2f", *slope), sortKey(*slope)) : emptyCell();
        }
        h += "</tr>\n";
    }
    h += "</tbody>\n</table></div>\n";
    h += "<p class=\"meta\">RMSE and max error: linear radiance over unmasked pixels; masked: "
         "share of pixels on silhouettes, shadow edges and coincident faces; tested: share of "
         "8x8 tiles with enough unmasked pixels for a test; speed ratio: POV-Ray's wall time "
         "(supersampled, edge-mask picture included) over scadray's. Click a heading to "
         "sort.</p>\n";

    // Sections
    std::string curves = "[";
    for (size_t i = 0; i < page.scenes.size(); ++i) {
        const ReportScene &s = page.scenes[i];
        int rank = s.rank();
        h += "<section id=\"scene-" + std::to_string(i) + "\" class=\"" + verdictClass(rank) +
             "\">\n<h2><span class=\"verdict\">" + verdictName(rank) + "</span> " +
             xmlEscape(s.name()) + " <a href=\"#summary\" class=\"top\">&uarr; table</a></h2>\n";
        if (!s.error.empty()) h += "<pre class=\"err\">" + xmlEscape(s.error) + "</pre>\n";
        if (s.povray) h += checkSection(*s.povray, s.povrayPictures);
        if (s.openscad) h += checkSection(*s.openscad, s.openscadPictures);
        if (!s.openscadNote.empty())
            h += "<p>OpenSCAD referee: " + xmlEscape(s.openscadNote) + "</p>\n";
        if (s.converge) {
            h += "<h3>Error against time (converge)</h3>\n";
            std::string title =
                fs::path(s.scene).filename().string() + ": error against render time";
            if (!page.chartJs.empty()) {
                h += "<div class=\"plot\"><canvas id=\"plot-" + std::to_string(i) +
                     "\" width=\"720\" height=\"440\"></canvas></div>\n";
                if (curves.size() > 1) curves += ",";
                curves += curveJson(s, i, title);
            } else if (!s.converge->svg.empty()) {
                // As a picture, never inline: an SVG read from a folder must not run script
                h += "<div class=\"plot\"><img src=\"data:image/svg+xml;base64," +
                     base64(s.converge->svg) + "\" alt=\"" + xmlEscape(title) + "\"></div>\n";
            }
        }
        h += "</section>\n";
    }
    curves += "]";
    h += "<p id=\"report-selfcheck\">checking pictures&hellip;</p>\n";
    h += "<script type=\"application/json\" id=\"converge-data\">" + curves + "</script>\n";
    h += "<script>" + std::string(kScript) + "</script>\n</body>\n</html>\n";
    return h;
}

std::string urlPath(const std::string &path) {
    std::string out;
    for (unsigned char c : path) {
        if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') {
            out += char(c);
        } else {
            char buf[4];
            std::snprintf(buf, sizeof buf, "%%%02X", c);
            out += buf;
        }
    }
    return out;
}

std::string dataUri(const std::string &folder, const std::string &name) {
    // Through the input reader and confined to the check's folder: a picture named by a
    // check's figures that is a link (to a secret, a FIFO, /dev/zero) is never embedded
    std::string bytes = readInputFileIn(folder, name, kMaxReportPictureBytes);
    std::string ext = fs::path(name).extension().string();
    const char *mime = ext == ".png"   ? "image/png"
                       : ext == ".svg" ? "image/svg+xml"
                                       : "application/octet-stream";
    return "data:" + std::string(mime) + ";base64," + base64(bytes);
}

std::string base64(const std::string &bytes) {
    static const char *kAlphabet =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        uint32_t v = uint32_t(uint8_t(bytes[i])) << 16 | uint32_t(uint8_t(bytes[i + 1])) << 8 |
                     uint8_t(bytes[i + 2]);
        out += kAlphabet[v >> 18];
        out += kAlphabet[(v >> 12) & 63];
        out += kAlphabet[(v >> 6) & 63];
        out += kAlphabet[v & 63];
    }
    if (i < bytes.size()) {
        uint32_t v = uint32_t(uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size()) v |= uint32_t(uint8_t(bytes[i + 1])) << 8;
        out += kAlphabet[v >> 18];
        out += kAlphabet[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

std::string findChartJs() {
    if (const char *env = std::getenv("SCADRAY_CHARTJS"); env && *env)
        return fs::is_regular_file(env) ? env : "";
    // Debian 12's libjs-chart.js (3.9) ships the UMD build as chart.min.js; later releases
    // (4.x) keep it under /usr/share/nodejs as chart.umd.js
    for (const char *p : {"/usr/share/javascript/chart.js/chart.min.js",
                          "/usr/share/nodejs/chart.js/dist/chart.umd.js",
                          "/usr/share/javascript/chart.js/chart.umd.js",
                          "/usr/share/nodejs/chart.js/dist/chart.min.js"})
        if (fs::is_regular_file(p)) return p;
    return "";
}

}  // namespace rt::cli
