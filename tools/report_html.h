// SPDX-License-Identifier: MIT
// The HTML page of `scadray report`: a summary, a sortable table of scenes (failures first),
// and per scene the pictures side by side, the figures, and the error-against-time plot.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tools/check.h"

namespace rt::cli {

/// One `scadray converge` run as its CSV holds it, plus its own SVG plot.
struct ConvergeCurve {
    std::vector<int> samples;
    std::vector<double> seconds;
    std::vector<double> rmse;        ///< against scadray's converged reference, noise-corrected
    std::vector<double> rmsePovray;  ///< against POV-Ray; empty when not measured
    /// The SVG converge wrote, shown instead of the interactive plot where no Chart.js was
    /// found to embed
    std::string svg;
};

/// Largest file a report reads back (a check's figures, converge's CSV and SVG); a check's
/// pictures may be up to kMaxReportPictureBytes.
constexpr uint64_t kMaxReportFileBytes = uint64_t{16} << 20;
constexpr uint64_t kMaxReportPictureBytes = uint64_t{256} << 20;

/// Reads converge's CSV (samples,seconds,rmse,rmse_corrected,efficiency,rmse_povray). Throws
/// std::runtime_error naming the file when it is missing or malformed.
ConvergeCurve readConvergeCsv(const std::string &path);

/// Reads what converge left in `folder` for a scene of file stem `stem`: `<stem>_converge.csv`
/// and, when there, `<stem>_converge.svg`. Each must lie in `folder` (links resolved), be a
/// regular file and at most kMaxReportFileBytes. Throws std::runtime_error naming the file.
ConvergeCurve readConvergeFiles(const std::string &folder, const std::string &stem);

/// A check's three pictures as the page refers to them (data: URIs or relative links), in
/// the order referee, scadray, difference; empty where the check made none.
using PictureSources = std::array<std::string, 3>;

/// One row of the table and its section: the POV-Ray check, the OpenSCAD check, converge,
/// each when run.
struct ReportScene {
    std::string scene;  ///< the scene file as given
    std::string label;  ///< how the page names it (empty: `scene`)
    std::optional<CheckResult> povray, openscad;
    PictureSources povrayPictures, openscadPictures;
    std::optional<ConvergeCurve> converge;
    /// Why a part could not run that is no check's (converge failed, a JSON was unreadable)
    std::string error;
    /// Why the OpenSCAD referee did not look at this scene (not a .scad file)
    std::string openscadNote;

    /// 0 error, 1 different, 2 pass: the table's default order
    int rank() const;
    const std::string &name() const { return label.empty() ? scene : label; }
};

/// Failures first (errors, then differences), then passes; by scene name within each.
void sortFailuresFirst(std::vector<ReportScene> &scenes);

struct ReportPage {
    std::string title = "scadray report";
    std::string settings, generated;  ///< shown in the header
    double wallSeconds = 0;           ///< the whole report's run
    std::vector<ReportScene> scenes;  ///< in the order the table shows them
    /// Chart.js's UMD build, embedded once; empty: converge plots are converge's SVGs
    std::string chartJs;
};

/// The whole self-contained page. Every text from a scene (names, errors, reports) is
/// escaped. A script in the page writes what it found into #report-selfcheck once every
/// picture has loaded or failed: data-rows, data-verdicts (the table's order), data-images,
/// data-broken and data-charts, and data-done="1" (what tests/integration/report_browser.sh
/// reads from a headless browser).
std::string reportHtml(const ReportPage &page);

/// The bytes of the file `name` in `folder` as a data: URI (image/png, image/svg+xml or
/// application/octet-stream by extension). The file must lie in `folder` (links resolved), be
/// a regular file and at most kMaxReportPictureBytes. Throws std::runtime_error naming it.
std::string dataUri(const std::string &folder, const std::string &name);

/// Standard base64 (RFC 4648, with padding).
std::string base64(const std::string &bytes);

/// A relative path as a URL path: every byte but letters, digits, '-', '.', '_', '~' and
/// '/' percent-encoded.
std::string urlPath(const std::string &path);

/// Where Debian's libjs-chart.js keeps Chart.js's UMD build (or $SCADRAY_CHARTJS); empty
/// when none is installed.
std::string findChartJs();

}  // namespace rt::cli
